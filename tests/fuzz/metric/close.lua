-- To-be-closed variables whose __close raises or loops while an error or the budget unwinds.
study {
  base = "base.lua",
  metrics = {
    { name = "raise", signals = { y = "/y" }, fn = function(s)
        local x <close> = setmetatable({}, { __close = function() error("in close") end })
        error("x")
      end },
    { name = "loop", signals = { y = "/y" }, fn = function(s)
        local x <close> = setmetatable({}, { __close = function() while true do pcall(error) end end })
        while true do end
      end },
  },
}
