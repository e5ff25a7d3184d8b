-- C-stack recursion: the study file requiring itself from a function, __index and gsub callbacks;
-- an error object whose __tostring loops.
if rawget(_G, "again") then require "study" end
study {
  base = "base.lua",
  metrics = {
    { name = "req", signals = { y = "/y" },
      fn = function(s) rawset(_G, "again", true) return require "study" end },
    { name = "index", signals = { y = "/y" }, fn = function(s)
        local t = setmetatable({}, { __index = function(t, k) return t[k .. "x"] end })
        return t.a
      end },
    { name = "gsub", signals = { y = "/y" }, fn = function(s)
        local function f(x) return (string.gsub(x, ".", f)) end
        return #f("abc")
      end },
    { name = "tostr", signals = { y = "/y" }, fn = function(s)
        error(setmetatable({}, { __tostring = function() while true do end end }))
      end },
    { name = "args", signals = { y = "/y" }, fn = function(s) return ("a"):find() + string.gmatch() end },
  },
}
