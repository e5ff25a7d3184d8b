-- A function that catches its budget error and tries again.
study {
  base = "base.lua",
  metrics = {
    { name = "retry", signals = { y = "/y" }, fn = function(s)
        while true do pcall(function() while true do end end) end
      end },
  },
}
