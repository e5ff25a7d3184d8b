-- The study file's own code: it runs again for the metric functions (state kept between calls).
local calls = 0
study {
  base = "base.lua",
  metrics = {
    { name = "count", signals = { y = "/y" }, fn = function(s) calls = calls + 1 return calls end },
    { name = "mut", signals = { y = "/y" }, fn = function(s)
        s.y[1] = "x"; s.time = nil
        study { metrics = {} }
        return 1
      end },
    { name = "after", signals = { y = "/y" }, fn = function(s) return calls end },
  },
}
