-- The paper's stiffness study (section 5.3, Fig. 23, Tables 7, 12-16; section 5.4, Table 8,
-- Fig. 24-25) where the flange is really loaded. On the paper's own case 3 our S1002/60E1 LUT
-- never reaches its flange (the largest flange "indentation" is a 0.026 mm gap), so K changes
-- nothing there (docs/studies.md, section 1). Here the same matrix runs on the hard case of
-- scenarios/hard/lut_stiff_flange.lua (bases/flange_curve.lua: R = 200 m, 15 m/s, ORE B176 high,
-- 6 s; the leading outer flange carries up to ~240 kN): KEC and LUT with K = 1e9 ... 7.075e13
-- N/m^1.5 (D = K/100, Table 3), prescribed spin (as efficiency_case3.lua);
--   efficiency (the paper's section 5.3 settings): RK4 and ABM at 1 ms, dopri5 and BDF at
--   rtol = atol = 1e-4 ... 1e-8 without a largest step;
--   accuracy (section 5.4, Table 8, Fig. 24): dopri5 and BDF at 1e-6 with the 1 ms largest step,
--   labelled "(paper Table 8 setting: 1 ms cap)";
--   Fig. 25 (flange indentation and force per K): ABM at 0.1 ms.
-- 3 repeats; about 5 minutes on one core.
--   ./wb study scenarios/studies/flange_stiffness.lua        (out/flange_stiffness/)
-- Outputs as efficiency_case3.lua: study_cost.csv/.png, study_failures.csv,
-- study_accuracy_lut_vs_kec.csv/.png, study_lut_integrators.png (Fig. 24),
-- study_lut_stiffness_abm_h_0.1ms.png (Fig. 25).
local lib = require "studies.lib"
local spin, h = lib.spin(true)
local cases = lib.stiffness_cases(lib.paper_solvers(h, { 1e-4, 1e-5, 1e-6, 1e-7, 1e-8 }), spin)
for _, c in ipairs(lib.accuracy_cases(spin)) do cases[#cases + 1] = c end
for _, c in ipairs(lib.stiffness_cases({ lib.fixed("abm", 1e-4) }, spin)) do
  cases[#cases + 1] = c
end

study {
  base = "bases/flange_curve.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = cases,
  repeats = 3,
}
