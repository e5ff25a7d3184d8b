-- hostile: expect="c_stack_overflow.lua:"
-- hostile: expect="stack overflow"
-- Recursion through metamethods (nested C calls).
local t = setmetatable({}, { __index = function(t, k) return t[k] end })
local x = t.a
