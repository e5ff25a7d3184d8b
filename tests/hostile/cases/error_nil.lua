-- hostile: expect="error_nil.lua:3: error called with nil"
-- error(nil).
error(nil)
