-- hostile: env=RAILBENCH_LUA_SECONDS:3
-- hostile: expect="endless loop?"
-- xpcall whose message handler loops too.
while true do
  xpcall(function() while true do end end, function() while true do end end)
end
