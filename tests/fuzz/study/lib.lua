-- A study built with the shipped helpers (scenarios/studies/lib.lua).
local lib = require "studies.lib"
local cases = {}
for _, m in ipairs({ "rk4", "abm" }) do
  cases[#cases + 1] = lib.merge({ label = "KEC " .. m }, lib.kec(), lib.fixed(m, 1e-3))
end
cases[#cases + 1] = lib.merge({ label = "LUT", role = "reference" }, lib.lut(1e10),
                              lib.adaptive("dopri5", 1e-8, 1e-3))
study { base = "base.lua", cases = cases, repeats = 1 }
