-- The Manchester wagon 1 (scenarios/vehicles/manchester_wagon1.lua) at 20 m/s on a tangent
-- without irregularities, S1002 on 60E1 at 1:30 (the inclination at which delta_r of S1002 on
-- 60E1 is smooth from the centre to the offset, docs/stability.md section 6): the wheelsets of
-- the leading bogie (ws1, ws2) have their right wheels worn uniformly by 0.3 mm in radius
-- (profiles/s1002_worn_0.3mm.txt), the trailing bogie's are new (tests/run/test_worn_wheels.cpp).
-- The contact method is the scenario's (--set).
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 600 } }, step = 0.5 }
profiles { wheel = "s1002", rail = "60e1", back_to_back = 1.360, gauge = 1.435, r0 = 0.46,
           inclination = 0.0333333333333333,
           wheelsets = { ws1 = { wheel_right = "profiles/s1002_worn_0.3mm.txt" },
                         ws2 = { wheel_right = "profiles/s1002_worn_0.3mm.txt" } } }
contact { method = "lut", creep = "polach", mu = 0.2364 }
vehicle (wagon { speed = 20, start = 20 })
c.abm(20, 1.25e-3)
run { output = { every = 0.01 }, duration = 8 }
