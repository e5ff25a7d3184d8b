-- hostile: expect="fastsim_grid.lua:7: contact.fastsim: unknown key 'strip' (did you mean 'strips'?)" expect="fastsim_grid.lua:7: contact.fastsim: elements must be <= 200, got 1e+09"
-- A FASTSIM grid with a misspelt key and an element count that would make every creep force
-- evaluation cost seconds: both refused where they are written, nothing is run.
track { segments = { tangent { length = 100 } } }
contact {
  method = "lut", creep = "fastsim",
  fastsim = { strip = 20, elements = 1e9 },
}
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
