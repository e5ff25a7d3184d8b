-- hostile: expect="not a regular file (a folder)"
-- A folder named like a module.
require "mod"
