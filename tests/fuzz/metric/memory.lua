-- Functions that ask for more memory than the budget.
study {
  base = "base.lua",
  metrics = {
    { name = "rep", signals = { y = "/y" }, fn = function(s) return #string.rep("x", 1 << 30) end },
    { name = "concat", signals = { y = "/y" }, fn = function(s)
        local x = "xxxxxxxx"
        for i = 1, 40 do x = x .. x end
        return #x
      end },
    { name = "signals", signals = { y = "/y" }, fn = function(s)
        local t = {}
        for i = 1, 1000 do t[i] = s end
        return #t
      end },
  },
}
