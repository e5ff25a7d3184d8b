-- hostile: expect="elastic_constraint_keys.lua:7: contact: normal_forces applies to the constraint methods" expect="elastic_constraint_keys.lua:7: contact: min_normal_force applies to the constraint methods" expect="elastic_constraint_keys.lua:8: contact: flange_stiffness applies to the constraint methods" expect="elastic_constraint_keys.lua:8: contact: dhat applies to method 'kec' only"
-- Keys of the constraint methods given to the elastic method would be silently unused (it has
-- no normal-force coupling, no constraint normal force, no table flange, no KEC band): each is
-- refused at its line.
track { segments = { tangent { length = 100 } } }
contact { method = "elastic", creep = "polach",
  normal_forces = "lagged", min_normal_force = 1000,
  flange_stiffness = 1e10, dhat = 1e-3 }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
