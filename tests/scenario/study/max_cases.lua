-- Three cases with the limit lowered to two: refused; tests raise it through the same key.
study {
  base = "base_a.lua",
  matrix = { ["solver.method"] = { "rk4", "abm", "bdf" } },
  max_cases = 2,
}
