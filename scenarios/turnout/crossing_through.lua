-- The Manchester benchmark wagon 1 (scenarios/vehicles/manchester_wagon1.lua) over the common
-- crossing of a 60E1 1:9 turnout on the through route at 72 km/h: the right wheels run from the
-- wing rail onto the crossing nose (scenarios/turnout/lib.lua, crossing_rails: its geometry and
-- ASSUMPTIONS), on a flexible track (contact.elastic.rail_support, docs/track_support.md: a 150 kg
-- rail mass per wheel on 100 MN/m and 50 kN s/m vertically, 40 MN/m and 50 kN s/m laterally, an
-- ASSUMPTION of the order of a ballasted track). A tangent, no irregularities, no check rail (the
-- wheelset runs centred; a check rail on the other side would hold the flange off the nose's tip
-- if it did not). S1002 wheels on 60E1 at 1:40, elastic contact, Polach creep with the paper's
-- mu = 0.2364. The theoretical point is at s = 60 m; the leading wheelset starts 10 m before it.
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
local turnout = require "turnout.lib"
local tp, speed = 60, 20
local wing, nose = turnout.crossing_rails(tp, 200)
track { segments = { tangent { length = 200 } }, step = 0.25 }
profiles { wheel = "s1002", rail = "slices/60e1.txt", back_to_back = 1.360, gauge = 1.435,
           r0 = 0.46, inclination = 0.025,
           rail_slices = { right = wing }, extra_rails = { right = { nose } } }
contact { method = "elastic", creep = "polach", mu = 0.2364,
          elastic = { rail_support = { mass = 150, k_z = 1e8, c_z = 5e4, k_y = 4e7, c_y = 5e4 } } }
-- The leading wheelset at s = 50 m: the wagon's reference point 10.78 m behind it.
vehicle (wagon { speed = speed, start = tp - 10 - 10.78 })
c.abm(speed, 1e-4)
-- Until the trailing wheelset has passed the nose (it starts 21.56 m behind the leading one);
-- 2 kHz output for the impact at the nose.
run { output = { every = 0.0005 }, distance = 36, assessment = { safety = true } }
