-- The Manchester benchmark wagon 1 (scenarios/vehicles/manchester_wagon1.lua) into the diverging
-- route of a right-hand 60E1 turnout with a 190 m switch radius (scenarios/turnout/lib.lua: its
-- geometry and ASSUMPTIONS) at 40 km/h, the diverging route's permitted speed for that radius
-- (ASSUMPTION, as for the German EW 60-190-1:9 turnout). The curve has no transition and no cant:
-- 0.65 m/s^2 uncompensated lateral acceleration. The left wheels move from the straight stock
-- rail onto the curved switch blade. The run ends before the crossing: on the diverging route the
-- flange of the outer wheel is held off the nose by a check rail on the other side, and a check
-- rail (a contact on the back of the flange) is not modelled (docs/turnouts.md).
-- S1002 wheels on 60E1 at 1:40, every rail of the turnout in the same 1:40 frame (ASSUMPTION:
-- turnouts are often laid with vertical rails and inclined heads), elastic multi-point contact
-- (the only method that sees several rails), Polach creep with mu = 0.2364 (the paper's), no
-- irregularities. The toe is at s = 60 m; the leading wheelset starts 10 m before it.
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
local turnout = require "turnout.lib"
local toe, after, speed = 60, 60, 40 / 3.6
local stock, blade = turnout.switch_rails(toe, toe + turnout.curve_length + after)
track { segments = turnout.diverging_track(toe, after), step = 0.25 }
profiles { wheel = "s1002", rail = "slices/60e1.txt", back_to_back = 1.360, gauge = 1.435,
           r0 = 0.46, inclination = 0.025,
           rail_slices = { left = stock }, extra_rails = { left = { blade } } }
contact { method = "elastic", creep = "polach", mu = 0.2364 }
-- The leading wheelset at s = 50 m: the wagon's reference point 10.78 m behind it.
vehicle (wagon { speed = speed, start = 39.22 })
c.abm(speed, 2.5e-4)
-- Until the leading wheelset reaches the crossing, 23.5 m after the toe (scenarios/turnout/lib.lua;
-- the crossing of the diverging route needs a check rail, not modelled): the leading bogie runs
-- through the switch panel, the trailing one enters it.
run { output = { every = 0.005 }, distance = 33.5,
      assessment = { safety = true, wear = true } }
