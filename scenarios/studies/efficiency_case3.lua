-- Paper section 5.3 (Tables 7, 12-16, Fig. 23) and 5.4 (Table 8, Fig. 24) on our model: Manchester
-- wagon, R = 500 m, V = 20 m/s, 500 m with ORE B176 low irregularities (case 3), KEC and LUT
-- (K = 1e9 ... 7.075e13 N/m^1.5, D = K/100 as in Table 3).
--   Efficiency (the paper's section 5.3 settings, lib.paper_solvers): RK4 and ABM at 1 ms, dopri5
--   (ode45) and BDF (ode15s) at rtol = atol = 1e-4, 1e-5, 1e-6 WITHOUT a largest step; for the
--   paper's Table 7 (K = 7.075e13, where the paper needed ode15s 1e-7 / ode45 1e-8) also dopri5
--   1e-7, 1e-8 and BDF 1e-7, for KEC too (our KEC/LUT ratio there; the paper has no KEC row).
--   Accuracy (section 5.4, lib.accuracy_cases): dopri5 and BDF at 1e-6 with the 1 ms largest
--   step the paper states there, every model, labelled "(paper Table 8 setting: 1 ms cap)".
-- 3 repeats (CPU time as the median, evaluation counts exact); about 6 minutes on one core.
--   ./wb study scenarios/studies/efficiency_case3.lua          (out/efficiency_case3/)
-- Figures and tables: study_cost.png/.csv (Fig. 23, Tables 7, 12-16), study_failures.csv,
-- study_accuracy_lut_vs_kec.csv/.png (Eq. 33, Table 8: the LUT/KEC pairs of this study),
-- study_lut_integrators.png (Fig. 24), study_lut_stiffness_*.png.
--
-- Wheelset spin: prescribed (V / r_c, contact.wheelset_spin = "prescribed") in every case, so
-- that RK4 and ABM run at the paper's 1 ms: with the free spin (our default model) its creep mode
-- (about -2400 1/s at 20 m/s) limits ABM to about 0.5 ms (docs/contact_dynamics.md, section 7).
-- The free-spin model with every integrator is in work_precision.lua. false: free spin with
-- 0.25 ms fixed steps.
local PRESCRIBED_SPIN = true

local lib = require "studies.lib"
local spin, h = lib.spin(PRESCRIBED_SPIN)
local cases = lib.stiffness_cases(lib.paper_solvers(h, { 1e-4, 1e-5, 1e-6 }), spin)
-- Table 7: the Hertzian flange stiffness 7.075e13 at tighter tolerances, and KEC beside it.
for _, s in ipairs({ lib.adaptive("dopri5", 1e-7, 0), lib.adaptive("dopri5", 1e-8, 0),
                     lib.adaptive("bdf", 1e-7, 0) }) do
  cases[#cases + 1] = lib.merge(lib.lut(7.075e13), s, spin)
  cases[#cases + 1] = lib.merge(lib.kec(), s, spin)
end
-- Table 8 and Fig. 24: the accuracy settings.
for _, c in ipairs(lib.accuracy_cases(spin)) do cases[#cases + 1] = c end

study {
  base = "case3_base.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = cases,
  repeats = 3,
}
