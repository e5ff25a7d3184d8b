-- hostile: expect="pattern_find.lua:5:"
-- hostile: expect="pattern too costly"
-- Exponential backtracking runs in C, where no hook fires.
local s = string.rep("a", 5000)
local i = string.find(s, string.rep("a*", 30) .. "b")
