study {
  base = "base.lua",
  matrix = { ["solver.step"] = { 1e-3, 0.001, "1e-3" } },
  cases = { { label = "a" }, { label = "b" } },
}
