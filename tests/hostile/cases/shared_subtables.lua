-- hostile: expect="more than 500000 values"
-- A small table shared a thousand times: expands to a million values in the tree.
local row = {}
for i = 1, 1000 do row[i] = i end
local grid = {}
for i = 1, 1000 do grid[i] = row end
track { segments = { tangent { length = 100 } }, grid = grid }
