-- The matrix of paper_settings.lua (lib.paper_settings_cases: KEC and LUT K = 7.075e13, RK4/ABM
-- at 1 ms, dopri5 and BDF with and without the 1 ms cap) where the flange is loaded: the hard
-- case's set-up (bases/flange_curve.lua: R = 200 m, 15 m/s, ORE B176 high, 6 s; the leading
-- outer flange carries up to ~240 kN). The paper (Table 7) found RK4 and ABM at 1 ms failing
-- with this K once the flange is in contact; here those failures are results
-- (study_failures.csv). 3 repeats, one case at a time.
--   ./wb study scenarios/studies/paper_settings_flange.lua   (out/paper_settings_flange/)
local lib = require "studies.lib"

study {
  base = "bases/flange_curve.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = lib.paper_settings_cases(),
  repeats = 3,
  jobs = 1,
}
