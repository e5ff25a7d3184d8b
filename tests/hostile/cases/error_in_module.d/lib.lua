-- a module that fails
local x = 1
error({})
