study {
  base = "base_a.lua",
  cases = {
    { ["solver.step"] = 1e-3, label = "a" },
    { ["solver.step"] = 1e-3, label = "b" },
  },
}
