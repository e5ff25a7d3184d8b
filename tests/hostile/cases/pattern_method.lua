-- hostile: expect="pattern_method.lua:5:"
-- hostile: expect="string.match: pattern too costly"
-- The same through the string metatable (s:match).
local s = string.rep("a", 200)
local m = s:match(".-.-.-.-.-.-.-.-b")
