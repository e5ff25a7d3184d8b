-- hostile: expect="more than 500000 values"
-- Wide tables: a million entries.
local t = {}
for i = 1, 1000000 do t[i] = i end
track { segments = { tangent { length = 100 } }, big = t }
