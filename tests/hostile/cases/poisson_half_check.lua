-- hostile: exit=0 expect="poisson_half_check.lua: ok" reject="internal error"
-- contact.poisson = 0.5 is the upper end of the schema's range [0, 0.5] (an incompressible
-- material, a column of Kalker's table): every creep law takes it. It was an internal error
-- (exit 3) in the creep laws' Hertz patch, which required nu < 0.5.
track { segments = { tangent { length = 100 } } }
contact { method = "kec", creep = "polach", poisson = 0.5 }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
