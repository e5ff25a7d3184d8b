-- hostile: expect="error_number.lua:4: error 42"
-- error(42).
local x = 1
error(42)
