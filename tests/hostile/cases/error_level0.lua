-- hostile: expect="error_level0.lua:3: no position"
-- error with level 0 gives no position itself.
error("no position", 0)
