local s = string.rep("a", 40) .. "b"
local p = string.rep("a*", 30) .. "c"
string.find(s, p)
