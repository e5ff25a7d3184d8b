-- hostile: expect="memory_rep.lua:"
-- hostile: expect="memory budget of 1024 MiB"
-- One allocation beyond the budget.
local s = string.rep("x", 2000000000)
