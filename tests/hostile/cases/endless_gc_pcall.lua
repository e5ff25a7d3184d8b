-- hostile: expect="endless_gc_pcall.lua:6: reached the end"
-- Hiding the refusal behind pcall does not help: no object gets a finalizer, collectgarbage
-- returns, and the script goes on to its end.
for i = 1, 10 do pcall(setmetatable, {}, { __gc = function() while true do end end }) end
collectgarbage()
error("reached the end")
