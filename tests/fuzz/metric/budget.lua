-- A function that exceeds its instruction budget; the state is dead for the next ones.
study {
  base = "base.lua",
  metrics = {
    { name = "loop", signals = { y = "/y" }, fn = function(s) while true do end end },
    { name = "next", signals = { y = "/y" }, fn = function(s) return 1 end },
  },
}
