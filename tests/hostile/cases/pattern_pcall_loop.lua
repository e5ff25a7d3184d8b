-- hostile: env=RAILBENCH_LUA_SECONDS:3
-- hostile: expect="pattern too costly"
-- hostile: expect="reached"
-- A refused pattern caught by pcall is a normal error; the guard still bounds each call.
local s = string.rep("a", 5000)
for i = 1, 100 do pcall(string.find, s, string.rep("a*", 30) .. "b") end
error("reached: " .. select(2, pcall(string.find, s, string.rep("a*", 30) .. "b")))
