local t = {}
local c = t
for i = 1, 40 do c[1] = {}; c = c[1] end
study { base = "base.lua", matrix = { ["run.distance"] = t }, cases = { t }, metrics = t }
