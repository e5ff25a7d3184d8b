-- hostile: expect="fastsim_wrong_law.lua:6: contact: fastsim applies to creep = \"fastsim\" only (creep = \"polach\")"
-- A FASTSIM grid given to another creep law would be silently unused: refused at its line.
track { segments = { tangent { length = 100 } } }
contact {
  method = "lut", creep = "polach",
  fastsim = { strips = 20 },
}
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
