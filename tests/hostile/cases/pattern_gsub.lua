-- hostile: expect="string.gsub: pattern too costly"
-- gsub with a callback.
local s = string.rep("a", 3000)
local r = s:gsub("a-a-a-a-a-b", function(x) return x end)
