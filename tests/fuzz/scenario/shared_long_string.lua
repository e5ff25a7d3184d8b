-- One long string used for 4000 values: 4 GB as the tree's copies (was out of memory).
local s = ("x"):rep((1 << 20) - 16)
local v = {}
for i = 1, 4000 do v[i] = s end
run { output = { elements = v } }
