-- Every statistic and window of the signal, steady and error kinds.
study {
  base = "base.lua",
  cases = { { role = "reference" } },
  metrics = {
    { name = "a", signal = "/bodies/ws/y", stat = "max" },
    { name = "b", signal = "/bodies/ws/y", stat = "min", from = 0, to = 400 },
    { name = "c", signal = "/bodies/ws/y", stat = "max_abs", from = 2, to = 3 },
    { name = "d", signal = "/bodies/ws/y", stat = "mean", from = -1e300, to = 1e300 },
    { name = "e", signal = "/bodies/ws/y", stat = "rms", along = "time", from = 4.5, to = 5 },
    { name = "f", signal = "/bodies/ws/y", stat = "std", from = 0, to = 0.5 },
    { name = "g", signal = "/bodies/ws/y", stat = "half_peak_to_peak", to = 390 },
    { name = "h", signal = "/bodies/ws/y", stat = "final", from = 395 },
    { name = "s1", kind = "steady", signal = "/bodies/ws/y" },
    { name = "s2", kind = "steady", signal = "/bodies/ws/y", length = 1e-300, tolerance = 0 },
    { name = "s3", kind = "steady", signal = "/bodies/ws/y", length = 1e300, from = 1, to = 2 },
    { name = "e1", kind = "error", signal = "/bodies/ws/y" },
    { name = "e2", kind = "error", signal = "/bodies/ws/y", from = 0.5, to = 0.75, along = "time" },
  },
}
