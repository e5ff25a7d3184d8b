-- What a user gets: the shipped scenes as they are, outputs and the whole assessment on
-- (docs/performance.md, "The default scene as shipped"), on the paper's case 3 (Manchester wagon,
-- R = 500 m, V = 20 m/s, 500 m with ORE B176 low irregularities, 24.46 s simulated):
--   1. the default scene of ./wb run, scenarios/default/case3_kec_fast.lua (KEC, free spin,
--      consistent normal forces, ABM 1.25 ms with the stiff components integrated exponentially):
--      at least 100x real time within 0.05 mm of a dopri5 1e-10 reference on every wheelset;
--   2. the default scene before it, the validation case scenarios/validation/case3_kec.lua (the
--      paper's ABM 0.25 ms step): the side-by-side "before";
--   3. the same validation case with the paper's prescribed spin at ABM 1 ms (the model of the
--      paper's own runs), as shipped otherwise: at least 150x;
--   4. the reference: the validation case under dopri5 at rtol = atol = 1e-10.
-- jobs = 1 (one case at a time: timings undisturbed by a parallel case), 3 repeats, median.
--   ./wb study scenarios/studies/default_scene.lua             (out/default_scene/)
local lib = require "studies.lib"
local prescribed = lib.spin(true)

study {
  base = "../validation/case3_kec.lua",
  -- Full case files, as a plain run writes them: this study measures what a user's run costs.
  output = "full",
  cases = {
    { label = "default scene: KEC ABM 1.25 ms exponential, free spin (target 100x)",
      base = "../default/case3_kec_fast.lua" },
    { label = "before: KEC ABM 0.25 ms exponential, free spin (validation case 3)" },
    lib.merge({ label = "KEC ABM 1 ms exponential, prescribed spin (target 150x)" },
              lib.exponential("abm", 1e-3), prescribed),
    lib.merge({ label = "reference: KEC dopri5 1e-10, free spin", role = "reference" },
              lib.adaptive("dopri5", 1e-10, 0), { ["solver.max_steps"] = 1000000 }),
  },
  repeats = 3,
  jobs = 1,
}
