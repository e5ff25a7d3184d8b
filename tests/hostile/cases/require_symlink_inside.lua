-- hostile: exit=0
-- hostile: symlink=alias.lua:real.lua
-- A symlink that stays inside the scenario's folder is fine.
local segs = require "alias"
track { segments = segs }
