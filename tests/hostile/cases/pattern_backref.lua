-- hostile: expect="pattern too costly"
-- Back-references and balanced matches scan the subject too.
local s = string.rep("a", 2000)
local r = s:find("(a*)%1(a*)%2(a*)%3c")
