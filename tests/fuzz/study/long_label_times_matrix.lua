local b = {}
for i = 1, 5000 do b[i] = i end
study { base = "base.lua", matrix = { ["run.y"] = b }, cases = { { label = ("x"):rep(1000000) } } }
