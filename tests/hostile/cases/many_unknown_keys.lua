-- hostile: expect="unknown key 'k99999'"
-- 100000 named keys: reported, without quadratic work.
local t = { segments = { tangent { length = 100 } } }
for i = 1, 100000 do t["k" .. i] = i end
track(t)
