-- 100^4 cases: refused before expansion.
local v = {}
for i = 1, 100 do v[i] = i end
study { base = "base.lua", matrix = { ["a.w"] = v, ["a.x"] = v, ["a.y"] = v, ["a.z"] = v } }
