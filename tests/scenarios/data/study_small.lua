-- Test study: 2 x 2 matrix over a short guided run, one case whose runs fail when their model is
-- built (a 3 ms step does not divide the 10 ms output interval): each such run is recorded as an
-- error and the study goes on.
study {
  base = "study_base.lua",
  matrix = { ["solver.method"] = { "rk4", "abm" }, ["run.duration"] = { 0.2, 0.3 } },
  cases = { {}, { ["solver.step"] = 3e-3 } },
  repeats = 1,
  jobs = 2,
}
