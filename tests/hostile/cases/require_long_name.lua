-- hostile: expect="require_long_name.lua:4:"
-- hostile: expect="longer than 200 characters"
-- A 5000-character module name (was an exception through Lua frames, exit 3).
require(string.rep("a", 5000))
