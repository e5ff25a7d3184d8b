local ok, e = pcall(require, "../../etc/passwd")
local ok2 = pcall(require, "studies")
local tracks = require "tracks.lib"
study { base = "base.lua", cases = { { label = tostring(ok) .. tostring(ok2) .. type(tracks) } } }
