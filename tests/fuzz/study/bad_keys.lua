study {
  bsae = "base.lua",
  matrix = { ["solver.method"] = "rk4", [1] = { 1 } },
  cases = { { lable = "x" }, { role = "referense" }, { base = "missing.lua" }, 3 },
  repeats = 0,
  jobs = 1.5,
  max_cases = 1e300,
  output = "everything",
}
track { segments = {} }
