-- hostile: expect="constructor_misuse.lua:3: track expects one table of named values"
-- A constructor called with a string.
track "main line"
