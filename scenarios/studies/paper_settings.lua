-- The paper's solver settings measured on our model (paper section 5.3): the KEC/LUT cost ratio
-- per integrator on the paper's case 3 (Manchester wagon, R = 500 m, V = 20 m/s, ORE B176 low,
-- 24.46 s), the adaptive methods with and without the 1 ms largest step (lib.paper_settings_cases).
-- With a 1 ms cap every adaptive run needs at least 24 461 steps, which hides how many steps
-- each contact model asks for; the paper's own counts (38 719 evaluations over 25 s for its KEC
-- with ode45 at 1e-4, 3.9 ms per step on average) show that its runs had no cap. 3 repeats, one
-- case at a time.
--   ./wb study scenarios/studies/paper_settings.lua          (out/paper_settings/)
-- The same matrix where the flange is loaded: paper_settings_flange.lua.
local lib = require "studies.lib"

study {
  base = "case3_base.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = lib.paper_settings_cases(),
  repeats = 3,
  jobs = 1,
}
