-- hostile: env=RAILBENCH_LUA_SECONDS:3
-- hostile: expect="endless_pcall_loop.lua:"
-- hostile: expect="endless loop?"
-- An endless loop inside pcall, in an endless loop: the budget error must not be swallowed.
while true do
  pcall(function() while true do end end)
end
