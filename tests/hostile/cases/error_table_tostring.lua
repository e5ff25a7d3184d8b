-- hostile: env=RAILBENCH_LUA_SECONDS:3
-- hostile: expect="error_table_tostring.lua:5: error called with a table value"
-- A __tostring that loops must not be called while reporting.
local e = setmetatable({}, { __tostring = function() while true do end end })
error(e)
