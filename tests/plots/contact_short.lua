-- A few tenths of a second of the Manchester wagon with wheel/rail contact, for the plot tests
-- (tests/plots/test_plots.py runs it with contact.method = kec and lut). The wagon starts inside
-- a sharp curve without cant (R = 150 m at 16 m/s: 1.7 m/s^2 of cant deficiency) so that the
-- leading wheelsets reach the outer flange within the run and the flange panels carry load.
track {
  segments = {
    tangent    { length = 10 },
    transition { length = 20, radius = 150, side = "left" },
    curve      { length = 60, radius = 150, side = "left" },
  },
  step = 0.5,
}
-- S1002 on 60E1 at 1:40 as in the paper's validation cases (scenarios/validation/common.lua).
profiles { wheel = "s1002", rail = "60e1", back_to_back = 1.360, gauge = 1.435, r0 = 0.46,
           inclination = 0.025 }
-- Only keys both contact methods accept, so --set contact.method=lut works.
contact { method = "kec", creep = "polach", mu = 0.2364 }
-- start: the leading wheelset (10.9 m ahead of the reference point) is 25 m into the curve.
vehicle (require "vehicles.manchester_wagon1" { speed = 16, start = 45 })
solver { method = "dopri5" }
-- Body accelerations and two suspension elements: the plots draw them when the file has them.
run { duration = 0.3, output = { every = 0.005, body_accelerations = true,
                                 elements = { "prim_z_ws1_l", "sec_z_bogie1_l" } } }
