-- hostile: symlink=mylib/secret.csv:{outside}/secret.lua
-- hostile: expect="library_data_outside.lua:"
-- hostile: expect="is outside the folders a scenario may read"
-- hostile: expect="'../../../../../../../../../etc/passwd' is outside the folders a scenario may read"
-- hostile: reject="SECRET"
-- A library's data files resolve beside the library first (LuaHost::resolveDataFile): that must
-- not open a way out of the sandbox, neither by a link beside the library to a file outside every
-- read root nor by a name that climbs out of the library's folder.
local lib = require "mylib.rails"
track { segments = { tangent { length = 300 } }, irregularities = lib.measured }
profiles { wheel = lib.wheel }
