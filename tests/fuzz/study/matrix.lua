-- A 2 x 2 matrix over the single wheelset, two explicit cases.
study {
  base = "base.lua",
  matrix = { ["solver.method"] = { "rk4", "abm" }, ["run.distance"] = { 2, 5.5 } },
  cases = { {}, { ["solver.step"] = 1e-4, label = "small step" } },
  repeats = 2,
  jobs = 1,
  max_cases = 8,
  output = "full",
}
