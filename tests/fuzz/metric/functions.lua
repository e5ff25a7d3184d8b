-- Function metrics over the signals: sums, NaN checks, the abscissa, library calls.
local function sum(t) local a = 0 for _, v in ipairs(t) do a = a + v end return a end
study {
  base = "base.lua",
  metrics = {
    { name = "n", fn = function(s) return #s.y end, signals = { y = "/bodies/ws/y" } },
    { name = "sum", fn = function(s) return sum(s.y) / math.max(#s.y, 1) end,
      signals = { y = "/bodies/ws/y" } },
    { name = "finite", signals = { y = "/bodies/ws/y" }, fn = function(s)
        local m = 0
        for _, v in ipairs(s.y) do if v == v and math.abs(v) < math.huge then m = math.max(m, v) end end
        return m
      end },
    { name = "dist", signals = { y = "/bodies/ws/y" },
      fn = function(s) return (s.distance[#s.distance] or 0) - (s.time[1] or 0) end },
    { name = "text", signals = { y = "/bodies/ws/y" },
      fn = function(s) return tonumber(string.format("%.3g", s.y[1] or 0)) end },
    { name = "sorted", signals = { a = "/bodies/ws/y", b = "/bodies/ws/z" }, fn = function(s)
        local t = table.pack(table.unpack(s.a))
        table.sort(t, function(x, y) return (x or 0) < (y or 0) end)
        return t[1] or -1
      end },
    { name = "utf", signals = { y = "/y" }, fn = function(s) return utf8.len("\u{20AC}") end },
    { name = "int", signals = { y = "/y" }, fn = function(s) return math.tointeger(#s.y) // 2 end },
  },
}
