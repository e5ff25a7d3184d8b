-- Paper section 5.2, case 3 (LUT): Manchester wagon 1 at V = 20 m/s on a 100 m tangent, 50 m
-- transition and 350 m left curve of R = 500 m, with the ORE B176 low irregularities of scenarios/tracks/manchester_r500_irregular.lua
-- (seed 42), Fig. 21-22.
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"

track {
  segments = lib.manchester_r500(),
  step = 0.5,
  -- ORE B176 low irregularities, seed 42 (scenarios/tracks/manchester_r500_irregular.lua).
  irregularities = psd {
    spectrum = "ore_b176_low",
    seed = 42,
    wavelengths = { 3, 70 },
    step = 0.1,
  },
}
-- Profiles: S1002 on 60E1 at 1:40, B = 1360 mm, G = 1435 mm, r0 = 0.46 m. The paper's
-- LB-140-Area rail (Table 1: Lw = 0.7515 m, Lr = 0.7555 m, r0 = 0.457 m) has no public head
-- geometry, so its positions cannot be used with 60E1 unchanged (docs/contact_dynamics.md).
profiles {
  wheel = "s1002",
  rail = "60e1",
  back_to_back = 1.360,
  gauge = 1.435,
  r0 = 0.46,
  inclination = 0.025,
  -- Paper Table 1 alternative (LB-140-Area positions; with 60E1 they mean B = 1363 mm and
  -- G ~ 1440 mm):
  -- lw = 0.7515, lr = 0.7555, r0 = 0.457,   (and remove back_to_back, gauge, r0 above)
}
-- LUT (paper section 2.3): Hertz flange with K = 1e10 N/m^1.5 (section 5.2), D = K/100 (Table 3).
contact { method = "lut", flange_stiffness = 1e10, creep = "polach", mu = 0.2364 }
vehicle (wagon { speed = 20 })
-- Solver: the paper's ABM (section 5.2), but not with its 1 ms step. Here the wheelset spin is
-- free and driven by the creep forces: the spin creep mode has an eigenvalue of about -2400 1/s
-- at V = 20 m/s (2 f11 r0^2 / (V I_yy)), and ABM (PECE, real stability limit h |lambda| < 1.28)
-- needs h < 0.54 ms (docs/contact_dynamics.md, "Time integration"). At 1 ms a perturbed spin rate
-- keeps oscillating (+-0.035 rad/s), bounded only by the creep law's nonlinearity; case 2 happens
-- to end on the same values (nothing excites the mode), case 3 differs by up to 0.5 mm (ws1 y).
-- Reproduce with --set solver.step=1e-3; dopri5 (adaptive) is the fastest choice.
solver { method = "abm", step = 2.5e-4 }
run { output = { every = 0.01 } }
