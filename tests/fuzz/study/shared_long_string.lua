-- One long string used for 4000 matrix values: 4 GB as the tree's copies (was out of memory).
local s = ("x"):rep((1 << 20) - 16)
local v = {}
for i = 1, 4000 do v[i] = s end
study { base = "base.lua", matrix = { ["run.x"] = v } }
