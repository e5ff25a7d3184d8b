-- hostile: expect="more than 500000 values"
-- a = {a, a} doubles the tree at each step without nesting deeply: 2^31 values.
local a = { 1, 2, 3 }
local wide = {}
for i = 1, 31 do wide[i] = a; a = { a, a } end
track { segments = { tangent { length = 100 } }, wide = wide }
