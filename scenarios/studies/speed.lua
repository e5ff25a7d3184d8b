-- The speed targets (docs/performance.md; a case's label states its target as "target Nx"), on
-- the paper's case 3 (Manchester wagon, R = 500 m, V = 20 m/s, 500 m with ORE B176 low
-- irregularities, 24.46 s simulated):
--   1. KEC + ABM at the paper's 1 ms step with the prescribed wheelset spin: at least 150x real
--      time (about 3 us per evaluation all-in).
--   2. The free-spin model (the scenario default) within 0.05 mm of the reference on every
--      wheelset: at least 100x. The explicit ABM needs 0.25 ms (the spin creep mode limits it to
--      0.54 ms, docs/integrators.md); with the stiff components integrated exponentially RK4 runs
--      at 2 ms (0.01 mm from the reference over case 3) and ABM at 1 ms.
--   3. LUT + BDF with the Hertzian flange stiffness K = 7.075e13 N/m^1.5 (paper Table 7: ode15s
--      needed rtol = atol = 1e-7), at 1e-6 and 1e-7 (the flange-loaded hard case: at least 10x,
--      docs/hard_cases.md).
-- jobs = 1 (one case at a time: timings undisturbed by a parallel case), 5 repeats, median.
--   ./wb study scenarios/studies/speed.lua                    (out/speed/)
local lib = require "studies.lib"
local prescribed = lib.spin(true)
local cases = {
  lib.merge({ label = "KEC ABM 1 ms, prescribed spin (target 150x)" }, lib.kec(),
            lib.fixed("abm", 1e-3), prescribed),
  lib.merge({ label = "LUT ABM 1 ms, prescribed spin" }, lib.lut(1e10), lib.fixed("abm", 1e-3),
            prescribed),
  lib.merge({ label = "KEC ABM 0.25 ms, free spin" }, lib.kec(), lib.fixed("abm", 2.5e-4)),
  lib.merge({ label = "KEC dopri5 1e-6, free spin" }, lib.kec(), lib.adaptive("dopri5", 1e-6, 1e-3)),
  -- The free-spin model at the paper's step sizes: the stiff components (spin rates, series-damper
  -- forces) integrated exponentially (docs/integrators.md), with the consistent normal forces
  -- (the lagged ones do not converge with the free spin, docs/contact_dynamics.md).
  lib.merge({ label = "KEC RK4 2 ms exponential, free spin, consistent (target 100x)" }, lib.kec(),
            lib.exponential("rk4", 2e-3), lib.consistent()),
  lib.merge({ label = "KEC ABM 1 ms exponential, free spin, consistent" }, lib.kec(),
            lib.exponential("abm", 1e-3), lib.consistent()),
  -- The reference of target 2's accuracy (docs/performance.md: "max |dy| vs reference" of the
  -- cases of the same model: KEC, free spin, consistent normal forces).
  lib.merge({ label = "reference: KEC dopri5 1e-10, free spin, consistent", role = "reference" },
            lib.kec(), lib.adaptive("dopri5", 1e-10, 0), lib.consistent(),
            { ["solver.max_steps"] = 1000000 }),
  lib.merge({ label = "LUT K=7.075e13 BDF 1e-6" }, lib.lut(7.075e13),
            lib.adaptive("bdf", 1e-6, 1e-3)),
  lib.merge({ label = "LUT K=7.075e13 BDF 1e-7 (paper's tolerance)" }, lib.lut(7.075e13),
            lib.adaptive("bdf", 1e-7, 1e-3)),
}

study {
  base = "case3_base.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = cases,
  repeats = 5,
  jobs = 1,
}
