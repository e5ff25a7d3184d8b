-- hostile: args="tables {case} --out t.h5"
-- hostile: expect="nested more than 32 levels"
-- The tables subcommand loads scenarios through the same host.
local t = {}
for i = 1, 100 do t = { t } end
track { segments = { tangent { length = 100 } }, deep = t }
