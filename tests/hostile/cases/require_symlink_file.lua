-- hostile: symlink=evil.lua:{outside}/secret.lua
-- hostile: expect="require_symlink_file.lua:6:"
-- hostile: expect="leads outside the folders modules may come from"
-- hostile: reject="SECRET"
-- A symlinked module file pointing outside.
local s = require "evil"
error(s.stolen)
