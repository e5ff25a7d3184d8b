-- hostile: expect="endless_gc.lua:4:"
-- hostile: expect="finalizers (__gc) are not allowed"
-- Lua runs finalizers with hooks off: an endless loop there could never be stopped.
local t = setmetatable({}, { __gc = function() while true do end end })
t = nil
collectgarbage()
