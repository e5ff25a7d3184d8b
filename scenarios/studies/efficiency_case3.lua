-- Paper section 5.3 (Tables 7, 12-16, Fig. 23) on our model: Manchester wagon, R = 500 m,
-- V = 20 m/s, 500 m with ORE B176 low irregularities (case 3), KEC and LUT (K = 1e9 ... 7.075e13
-- N/m^1.5, D = K/100 as in Table 3) with RK4 and ABM at a fixed step, dopri5 (ode45) and BDF
-- (ode15s) at rtol = atol = 1e-4, 1e-5, 1e-6 with a largest step of 1 ms; for the paper's
-- Table 7 (K = 7.075e13, where the paper needed ode15s 1e-7 / ode45 1e-8) also 1e-7 and 1e-8.
-- 5 repeats (CPU time as the median, evaluation counts exact). Long (about 5 minutes with 2 jobs on 2 cores):
--   ./wb study scenarios/studies/efficiency_case3.lua          (out/efficiency_case3/)
-- Figures and tables: study_cost.png/.csv (Fig. 23, Tables 7, 12-16), study_failures.csv,
-- study_accuracy_lut_vs_kec.csv/.png (Eq. 33, Table 8: the LUT/KEC pairs of this study),
-- study_lut_integrators.png (Fig. 24), study_lut_stiffness_*.png (Fig. 25).
--
-- Wheelset spin: prescribed (V / r_c, contact.wheelset_spin = "prescribed") in every case, so
-- that RK4 and ABM run at the paper's 1 ms: with the free spin (our default model) its creep mode
-- (about -2400 1/s at 20 m/s) limits ABM to about 0.5 ms (docs/contact_dynamics.md, section 7).
-- The free-spin model with every integrator is in work_precision.lua. false: free spin with
-- 0.25 ms fixed steps.
local PRESCRIBED_SPIN = true

local lib = require "studies.lib"
local spin, h = lib.spin(PRESCRIBED_SPIN)
local solvers = lib.paper_solvers(h, { 1e-4, 1e-5, 1e-6 })
local cases = lib.stiffness_cases(solvers, spin)
-- Table 7: the Hertzian flange stiffness 7.075e13 at tighter tolerances.
for _, s in ipairs({ lib.adaptive("dopri5", 1e-7, 1e-3), lib.adaptive("dopri5", 1e-8, 1e-3),
                     lib.adaptive("bdf", 1e-7, 1e-3) }) do
  cases[#cases + 1] = lib.merge(lib.lut(7.075e13), s, spin)
end

study {
  base = "case3_base.lua",
  cases = cases,
  repeats = 5,
}
