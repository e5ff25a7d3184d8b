-- hostile: expect="module names are names separated by dots"
-- Empty segments.
require "vehicles..manchester_wagon1"
