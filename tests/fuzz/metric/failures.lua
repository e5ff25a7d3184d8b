-- Functions that fail: an error, a string, nil, nothing, a table, inf, NaN, a missing signal.
study {
  base = "base.lua",
  metrics = {
    { name = "err", fn = function(s) error("no good") end, signals = { y = "/y" } },
    { name = "errt", fn = function(s) error({}) end, signals = { y = "/y" } },
    { name = "str", fn = function(s) return "x" end, signals = { y = "/y" } },
    { name = "none", fn = function(s) end, signals = { y = "/y" } },
    { name = "tab", fn = function(s) return s end, signals = { y = "/y" } },
    { name = "inf", fn = function(s) return 1 / 0 end, signals = { y = "/y" } },
    { name = "nan", fn = function(s) return 0 / 0 end, signals = { y = "/y" } },
    { name = "miss", fn = function(s) return s.nope[1] end, signals = { y = "/y" } },
    { name = "num", fn = function(s) return "12" end, signals = { y = "/y" } },
  },
}
