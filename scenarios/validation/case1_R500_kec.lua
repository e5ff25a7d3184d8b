-- Paper section 5.2, case 1 (KEC): single wheelset at V = 10 m/s on a 30 m tangent, 50 m
-- transition and 40 m left curve of R = 500 m, no irregularities (Fig. 16, 17, Table 5).
-- The wheelset hangs from a kinematic frame through the Manchester primary suspension
-- (scenarios/vehicles/single_wheelset.lua); with contact it is free in y, psi and theta, with z
-- and phi given by the contact constraints.
local lib = require "tracks.lib"
local ws = require "vehicles.single_wheelset"

track { segments = lib.validation(500), step = 0.5 }
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
-- KEC (paper section 2.4): tread-flange transition lengths 0.5 mm / 1 mm (section 2.4).
contact { method = "kec", dhat = 0.5e-3, dbar = 1e-3, creep = "polach", mu = 0.2364 }
vehicle (ws { speed = 10 })
-- Solver: the paper's ABM (section 5.2), but not with its 1 ms step. Here the wheelset spin is
-- free and driven by the creep forces: the spin creep mode has an eigenvalue of about -4700 1/s
-- at V = 10 m/s (2 f11 r0^2 / (V I_yy)), and ABM (PECE, real stability limit h |lambda| < 1.28)
-- needs h < 0.27 ms (docs/contact_dynamics.md, "Time integration"). At 1 ms the spin oscillates
-- from step to step, bounded only by the creep law's nonlinearity, and the wheelset settles at a
-- wrong position (R = 900 m: y = -0.18 mm instead of -0.40 mm).
-- Reproduce with --set solver.step=1e-3; dopri5 (adaptive) is the fastest choice.
solver { method = "abm", step = 2e-4 }
run { output = { every = 0.01 } }
