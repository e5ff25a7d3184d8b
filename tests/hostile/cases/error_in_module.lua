-- hostile: expect="lib.lua:3: error called with a table value"
-- The error is raised inside a required module.
require "lib"
