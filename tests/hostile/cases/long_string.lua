-- hostile: expect="long_string.lua:5:"
-- hostile: expect="longer than 1048576 bytes"
-- A 4 MB string value.
local s = string.rep("x", 4 * 1024 * 1024)
track { segments = { tangent { length = 100 } }, name = s }
