-- hostile: exit=0
-- hostile: reject="pattern too costly"
-- Ordinary string work still runs.
local function trim(s) return (s:gsub("^%s*(.-)%s*$", "%1")) end
assert(trim("   ab c  ") == "ab c")
local words = {}
for w in ("alpha beta gamma"):gmatch("%a+") do words[#words + 1] = w end
assert(#words == 3)
assert(("a.b.c"):find(".", 1, true) == 2)
assert(("x=1, y=2"):match("y=(%d+)") == "2")
local long = string.rep("word ", 800)
assert(select(2, long:gsub("%s+", " ")) == 800)
track { segments = { tangent { length = 100 } } }
