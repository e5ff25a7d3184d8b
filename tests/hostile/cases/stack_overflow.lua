-- hostile: expect="stack_overflow.lua:4:"
-- hostile: expect="stack overflow"
-- Unbounded Lua recursion.
local function f(n) return f(n + 1) + 1 end
f(1)
