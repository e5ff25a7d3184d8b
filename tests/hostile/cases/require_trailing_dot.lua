-- hostile: expect="module names are names separated by dots"
-- A trailing dot.
require "vehicles."
