-- Straight level track without irregularities: the Manchester wagon 1 (symmetric: every wheel
-- carries an eighth of the vehicle's weight) at 20 m/s, for the static test of the track-frame
-- wheel/rail forces (tests/app/test_wheel_forces.cpp). Profiles and contact constants of the
-- validation cases (scenarios/validation/common.lua); only keys both contact methods accept, so
-- --set contact.method=lut works.
local common = require "validation.common"
track { segments = { tangent { length = 200 } }, step = 0.5 }
common.profiles()
contact { method = "kec", creep = "polach", mu = 0.2364 }
vehicle (require "vehicles.manchester_wagon1" { speed = 20, start = 20 })
solver { method = "abm", step = 2.5e-4 }
run { duration = 0.2, output = { every = 0.01 } }
