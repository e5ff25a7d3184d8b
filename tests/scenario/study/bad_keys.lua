study {
  base = "base_a.lua",
  cases = {
    { lable = "x" },
    { role = "referense" },
    { base = "missing.lua" },
  },
}
