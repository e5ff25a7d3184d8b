-- hostile: expect="memory_growth.lua:"
-- hostile: expect="memory budget of 1024 MiB"
-- hostile: timeout=240
-- A table growing until the budget is exhausted.
local t = {}
for i = 1, 1e10 do
  t[i] = string.rep("z", 1 << 20) .. i
end
