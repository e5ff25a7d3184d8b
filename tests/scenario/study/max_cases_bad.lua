-- max_cases far beyond its range: a plain error, not a conversion out of int's range.
study {
  base = "base_a.lua",
  max_cases = 1e300,
}
