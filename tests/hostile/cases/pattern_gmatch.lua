-- hostile: expect="string.gmatch: pattern too costly"
-- gmatch.
local s = string.rep("ab", 500)
for w in s:gmatch("(a*)*(b*)*(a-)(b-)x") do end
