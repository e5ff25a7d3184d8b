-- Cost of each effect (issue 7, item 5): the paper's case 3 (KEC and LUT K = 1e10, ABM at a fixed
-- 0.25 ms step, so every variant makes the same number of right-hand side evaluations) with one
-- effect switched off or one extra output switched on at a time; the figure shows the CPU time
-- per evaluation of every variant relative to the full model (role "baseline"). A disabled
-- effect should cost nothing measurable: compare the difference with the repeat spread.
--   ./wb study scenarios/studies/effects.lua                  (out/effects/)
-- Outputs: study_effects.csv / .png (µs per evaluation, relative to the baseline, spread of
-- the repeats), study_cost.csv / .png, study_failures.csv.
-- Variants (bases in bases/, made by studies/wagon.lua):
--   no irregularities      the case-2 track (same curve, no irregularities)
--   no creep forces        contact.creep = "none" (normal contact only; the wagon then curves on
--                          its flanges, so the motion differs: the cost per evaluation still
--                          compares)
--   no flange contact      a 500 m tangent with the same irregularities: the flange is never
--                          reached (the engine evaluates the flange only when it indents: LUT
--                          Hertz force, KEC flange regime); this also removes curving
--   no bump stops          vehicle without its 2 lateral bump stops
--   plain dampers          the 16 series dampers as plain dampers (16 fewer states)
--   minimal                no irregularities, bump stops, series dampers
--   output every 1 ms      run.output.every = 1e-3 instead of 10 ms
--   body accelerations     run.output.body_accelerations = true
--   element outputs        deflection and force of all 50 elements
-- jobs = 1: one case at a time, so that parallel cases do not disturb the timings (close other
-- work while it runs); 5 repeats, median CPU time.
local cases = {
  { label = "full model", role = "baseline" },
  { label = "no irregularities", base = "bases/no_irregularities.lua" },
  { label = "no creep forces", ["contact.creep"] = "none" },
  { label = "no flange contact (tangent)", base = "bases/tangent.lua" },
  { label = "no bump stops", base = "bases/no_bumpstops.lua" },
  { label = "plain dampers", base = "bases/no_series_dampers.lua" },
  { label = "minimal", base = "bases/minimal.lua" },
  { label = "output every 1 ms", ["run.output.every"] = 1e-3 },
  { label = "body accelerations", ["run.output.body_accelerations"] = true },
  { label = "element outputs", base = "bases/element_outputs.lua" },
}

study {
  base = "case3_base.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  -- ABM 0.25 ms is the base scenario's solver; matrix values keep the two methods apart.
  matrix = { ["contact.method"] = { "kec", "lut" }, ["solver.step"] = { 2.5e-4 } },
  cases = cases,
  repeats = 5,
  jobs = 1,
}
