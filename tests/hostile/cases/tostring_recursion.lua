-- hostile: expect="tostring_recursion.lua:"
-- hostile: expect="stack overflow"
-- __tostring calling tostring on itself.
local t = setmetatable({}, { __tostring = function(x) return tostring(x) end })
print(t)
