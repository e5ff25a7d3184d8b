-- hostile: expect="module names are names separated by dots"
-- An embedded NUL would cut the name short in C.
require "a\0.b"
