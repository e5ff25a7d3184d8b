-- hostile: expect="require_leading_dot.lua:4:"
-- hostile: expect="module names are names separated by dots"
-- A leading '.' became '/', an absolute path.
local secret = require ".etc.passwd"
