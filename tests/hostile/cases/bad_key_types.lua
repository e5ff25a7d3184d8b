-- hostile: expect="keys must be names or list positions"
-- Boolean and fractional keys cannot be named in a scenario.
track { segments = { tangent { length = 100 } }, [true] = 1, [2.5] = 3 }
