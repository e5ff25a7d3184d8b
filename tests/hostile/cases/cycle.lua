-- hostile: expect="cycle.lua:6:"
-- hostile: expect="refers to itself (cycle)"
-- A table that contains itself.
local t = {}
t.self = t
track { segments = { tangent { length = 100 } }, loop = t }
