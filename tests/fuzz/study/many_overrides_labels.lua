local c, b = {}, {}
for i = 1, 2000 do c["run.k" .. i] = i end
for i = 1, 100 do b[i] = i end
study { base = "base.lua", matrix = { ["run.z"] = b }, cases = { c } }
