-- hostile: args="run {case} --out r.h5 --quiet"
-- hostile: expect="nested more than 32 levels"
-- The same through `run`, which crashed with a double free.
local t = {}
for i = 1, 200 do t = { x = t } end
track { segments = { tangent { length = 100 } }, deep = t }
