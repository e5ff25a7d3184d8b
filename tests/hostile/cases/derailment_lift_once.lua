-- hostile: expect="derailment_lift_once.lua:6: contact.elastic: derailment_lift must be in [0.001, 0.1] m or -1, got 0.5" expect="1 problem found"
-- A derailment lift above the range is one problem, said once (it was said twice: by the
-- schema's range and by the builder's own check of the same key).
track { segments = { tangent { length = 100 } } }
contact { method = "elastic", creep = "polach",
  elastic = { derailment_lift = 0.5 } }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
