local a, b = {}, {}
for i = 1, 100 do a[i] = ("x"):rep(600000) .. i; b[i] = i end
study { base = "base.lua", matrix = { ["run.x"] = a, ["run.y"] = b } }
