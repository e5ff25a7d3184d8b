-- Every metric kind, a function metric among them.
study {
  base = "base.lua",
  cases = { { role = "reference" }, { ["run.distance"] = 5 } },
  metrics = {
    { name = "y_max", signal = "/bodies/ws/y", stat = "max_abs", from = 100, to = 400 },
    { name = "y_mean", kind = "signal", signal = "/bodies/ws/y", stat = "mean", along = "time",
      from = 0, to = 1 },
    { name = "y_ss", kind = "steady", signal = "/bodies/ws/y", length = 50, tolerance = 1e-4 },
    { name = "yq", kind = "assessment", quantity = "y_over_q" },
    { name = "q", kind = "assessment", quantity = "/assessment/safety@y_over_q_max" },
    { name = "err", kind = "error", signal = "/bodies/ws/y", along = "time", from = 0.5 },
    { name = "vcrit", kind = "linear_critical_speed", speeds = { 20, 80, 4 } },
    { name = "f", fn = function(s) return #s.y end, signals = { y = "/bodies/ws/y" } },
    { name = "g", kind = "lua", signals = { y = "/bodies/ws/y", z = "/bodies/ws/z" },
      fn = function(s)
        local m = 0
        for i, v in ipairs(s.y) do m = math.max(m, math.abs(v - (s.z[i] or 0))) end
        return m
      end },
  },
}
