-- hostile: env=RAILBENCH_LUA_SECONDS:2
-- hostile: expect="endless_wallclock.lua:6:"
-- hostile: expect="time budget of 2 s"
-- Few instructions, each slow: the wall-clock budget stops it before the instruction budget.
while true do
  local s = string.rep("x", 4000000)
end
