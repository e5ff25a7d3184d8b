-- hostile: symlink=pkg:{outside}/pkg
-- hostile: expect="leads outside the folders modules may come from"
-- hostile: reject="SECRET"
-- A symlinked folder pointing outside.
local s = require "pkg.secret"
error(s.stolen)
