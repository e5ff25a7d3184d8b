-- tangent.lua with every output a run can write at once: body accelerations, element values and
-- patches, and the whole assessment sampled at the output times (tests/app/test_assessment.cpp:
-- the samplers share the model's evaluations of a state).
local common = require "validation.common"
track { segments = { tangent { length = 200 } }, step = 0.5 }
common.profiles()
contact { method = "kec", creep = "polach", mu = 0.2364 }
vehicle (require "vehicles.manchester_wagon1" { speed = 20, start = 20 })
solver { method = "abm", step = 2.5e-4 }
run { duration = 0.2,
      output = { every = 0.01, body_accelerations = true,
                 elements = { "prim_x_ws1_l", "sec_z_bogie1_l", "sec_bend_bogie1_l" } },
      assessment = { safety = true, stability = true, comfort = true, wear = true,
                     sample_every = 0.01 } }
