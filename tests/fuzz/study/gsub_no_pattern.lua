local t = {}
local c = t
for i = 1, 40 do c[1] = {}; c = c[1] end
study { base =string.gsub "base.lua", matrix = { ["2un.distance"] = t }, cases = { t }, metrics = t }
