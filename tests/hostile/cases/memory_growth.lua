-- hostile: expect="memory_growth.lua:"
-- hostile: expect="memory budget of 1024 MiB"
-- hostile: timeout=700 env=RAILBENCH_LUA_SECONDS:600
-- The time budget is raised so that the memory budget stops the script under the sanitizers too
-- (a clang ASan build takes about 2 minutes to fill 1 GiB here; the Release build seconds).
-- A table growing until the budget is exhausted.
local t = {}
for i = 1, 1e10 do
  t[i] = string.rep("z", 1 << 20) .. i
end
