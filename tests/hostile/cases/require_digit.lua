-- hostile: expect="module names are names separated by dots"
-- A segment starting with a digit.
require "vehicles.1wagon"
