-- hostile: expect="nested more than 32 levels"
-- Nesting through constructor tables, not only plain ones.
local t = tangent { length = 1 }
for i = 1, 100 do t = tangent { length = 1, inner = t } end
track { segments = { t } }
