-- hostile: expect="error_table.lua:4: error called with a table value"
-- error with a table value kept no location.
track { segments = { tangent { length = 100 } } }
error({ code = 1 })
