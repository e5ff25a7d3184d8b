-- hostile: expect="elastic_block_wrong_method.lua:6: contact: elastic applies to method = \"elastic\" only (method = \"kec\")"
-- The elastic method's block given to the KEC would be silently unused: refused at its line.
track { segments = { tangent { length = 100 } } }
contact {
  method = "kec", creep = "polach",
  elastic = { damping_ratio = 0.2 },
}
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
