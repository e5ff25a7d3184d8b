-- Functions that reach for what the sandbox refuses.
study {
  base = "base.lua",
  metrics = {
    { name = "io", fn = function(s) return io.open("/etc/passwd") end, signals = { y = "/y" } },
    { name = "os", fn = function(s) return os.time() end, signals = { y = "/y" } },
    { name = "load", fn = function(s) return load("return 1")() end, signals = { y = "/y" } },
    { name = "gc", signals = { y = "/y" }, fn = function(s)
        setmetatable({}, { __gc = function() while true do end end })
        return 1
      end },
    { name = "req", fn = function(s) return require("../../etc/passwd") end, signals = { y = "/y" } },
    { name = "req2", fn = function(s) local l = require "studies.lib" return 1 end,
      signals = { y = "/y" } },
    { name = "dbg", fn = function(s) return debug.sethook() end, signals = { y = "/y" } },
    { name = "co", fn = function(s) return coroutine.wrap(function() end)() end,
      signals = { y = "/y" } },
    { name = "raw", signals = { y = "/y" }, fn = function(s)
        rawset(_G, "string", nil)
        return #s.y
      end },
  },
}
