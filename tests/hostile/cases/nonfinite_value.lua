-- hostile: expect="nonfinite_value.lua:3: track: step must be finite"
-- 0/0 is NaN.
track { segments = { tangent { length = 100 } }, step = 0 / 0 }
