-- hostile: expect="require_not_string.lua:3: require expects a module name string"
-- A table for a name.
require {}
