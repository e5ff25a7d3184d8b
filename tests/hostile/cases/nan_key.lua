-- hostile: expect="nan_key.lua:5:"
-- hostile: expect="index is NaN"
-- A NaN table key.
local t = {}
t[0 / 0] = 1
