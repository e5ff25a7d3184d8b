-- hostile: expect="nested_deep.lua:8:"
-- hostile: expect="nested more than 32 levels"
-- 200 levels of plain tables (deep = t, line 8) overflowed the Lua stack in the conversion.
local t = {}
for i = 1, 200 do t = { t } end
track {
  segments = { tangent { length = 100 } },
  deep = t,
}
