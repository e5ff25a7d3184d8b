-- hostile: expect="tostring_not_string.lua:5:"
-- hostile: expect="__tostring"
-- print of a value whose __tostring returns a table.
local t = setmetatable({}, { __tostring = function() return {} end })
print(t)
