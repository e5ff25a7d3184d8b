-- hostile: env=RAILBENCH_LUA_SECONDS:3
-- hostile: expect="endless_pcall_then_return.lua:6:"
-- hostile: expect="endless loop?"
-- The loop is caught by pcall and the script ends normally: the run must still fail.
local ok = pcall(function()
  while true do end
end)
track { segments = { tangent { length = 100 } } }
