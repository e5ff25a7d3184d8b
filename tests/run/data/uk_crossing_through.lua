-- The S&C benchmark's UK crossing (56E1-R245-1:9.25, vertical rails; CONTACT's test bank,
-- tests/data/contact_sc/README.md) under the Manchester wagon 1 on the through route at 20 m/s:
-- the right rail is the crossing's 148 slices (wing rail, flangeway and nose in one profile,
-- kept whole by max_slope = 40), read from the slices-file directly; the left rail is the stock
-- rail opposite it with its check rail (their slices at CONTACT's section positions,
-- uk_opposite_stock_rail.slcs, uk_check_rail.slcs). The slices-files' u = 0 is at s = 80 m.
-- Rails placed as in CONTACT's cases: profile origins 750 mm from the track centre (RAILY0), no
-- inclination (CANT = 0), the wheels' profile origins at 750 mm too (flange backs 1360 mm
-- apart). Tangent, no irregularities, rigid rails. Elastic contact, Polach creep with the paper's
-- mu = 0.2364 (scenarios/validation/common.lua).
-- profiles.rail (the centred start's rail) is the 56E1 stock rail itself (the same points, in mm
-- with z up); every rail the wheels run on is a slice.
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
local data = "profiles/"
local s0, speed = 80, 20
track { segments = { tangent { length = 200 } }, step = 0.25 }
profiles { wheel = "s1002", rail = data .. "uk_crossing/stock_rail_56e1_mm.txt", lw = 0.750, lr = 0.750, r0 = 0.46, inclination = 0,
           rail_slices = {
             right = { slcs = data .. "uk_crossing.slcs", s = s0, units = "m", max_slope = 40 },
             left = { slcs = data .. "uk_opposite_stock_rail.slcs", s = s0, units = "m" } },
           extra_rails = { left = { { name = "check", check = true,
             slices = { slcs = data .. "uk_check_rail.slcs", s = s0, units = "m" } } } } }
contact { method = "elastic", creep = "polach", mu = 0.2364 }
-- The leading wheelset 8 m before the crossing's u = 0 (the wagon's reference point 10.78 m
-- behind it); until the trailing wheelset (21.56 m behind the leading one) is 4 m past it.
vehicle (wagon { speed = speed, start = s0 - 8 - 10.78 })
c.abm(speed, 1e-4)
run { output = { every = 0.0005 }, distance = 34, assessment = { safety = true } }
