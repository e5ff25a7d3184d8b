-- Test study: 2 x 2 matrix over a short guided run, one case with a bad option (it must be
-- recorded as an error, not abort the study).
study {
  base = "study_base.lua",
  matrix = { ["solver.method"] = { "rk4", "abm" }, ["run.duration"] = { 0.2, 0.3 } },
  cases = { {}, { ["solver.rtol"] = 1e-6 } },
  repeats = 1,
  jobs = 2,
}
