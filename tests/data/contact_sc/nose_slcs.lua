-- The crossing nose of CONTACT's S&C cases (cross_nose.slcs, 21 SIMPACK slices rising 1:10 from
-- u = -100 mm to +100 mm) as a further right rail of a tangent, read from the slices-file
-- directly, the file's u = 0 at s = 50 m, lowered by 50 mm (tests/run/test_slice_files.cpp).
-- Compiled and checked only: the test compares the rails, nothing runs over them.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
profiles { wheel = "s1002", back_to_back = 1.360, gauge = 1.435, r0 = 0.46, inclination = 0,
           extra_rails = { right = { { name = "nose",
             slices = { slcs = "cross_nose.slcs", s = 50, dz = -0.05 } } } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 30 })
solver { method = "abm", step = 5e-4 }
