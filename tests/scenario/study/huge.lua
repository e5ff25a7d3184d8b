-- A matrix of 100^4 = 1e8 cases: refused before it is expanded (it would need gigabytes).
local v = {}
for i = 1, 100 do v[i] = i end
study {
  base = "base_a.lua",
  matrix = { ["a.w"] = v, ["a.x"] = v, ["a.y"] = v, ["a.z"] = v },
}
