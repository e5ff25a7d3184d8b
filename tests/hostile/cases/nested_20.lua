-- hostile: expect="nested_20.lua:5: track: unknown key 'deep'"
-- About 20 levels were enough to overflow the unchecked Lua stack; now a plain unknown key.
local t = {}
for i = 1, 20 do t = { t, 1, "x" } end
track { segments = { tangent { length = 100 } }, deep = t }
