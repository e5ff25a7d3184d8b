-- An xpcall whose message handler loops.
study {
  base = "base.lua",
  metrics = {
    { name = "handler", signals = { y = "/y" }, fn = function(s)
        return xpcall(function() while true do end end, function() while true do end end)
      end },
  },
}
