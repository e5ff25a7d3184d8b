-- hostile: expect="memory budget of 1024 MiB"
-- A separator makes string.rep twice as large as its count suggests.
local s = ("x"):rep(700000000, ",")
