study {
  base = "base.lua",
  metrics = {
    { name = "a", signal = "/bodies/ws/y", stat = "maxx", from = 1 / 0, to = 0 / 0 },
    { name = "a", kind = "error", signal = "bodies//y" },
    { name = "1x", kind = "steady", signal = "/y", length = -1, tolerance = -2 },
    { name = "b_why", kind = "assessment", quantity = "/other@x", along = "time" },
    { name = "definitions_hash", kind = "linear_critical_speed", speeds = { 80, 20, 1e9 } },
    { name = "c", kind = "lua", signals = { 1, 2 } },
    { name = "d", fn = "return 1", signals = { y = "/y/" } },
    { name = "e", kind = "rainflow", colour = 1 },
    { 1, 2, 3 },
    "x",
  },
}
