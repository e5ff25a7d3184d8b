-- Test scenario: the single wheelset file on the paper's case-1 track, R = 500 m (tests/vehicle).
local ws = require "vehicles.single_wheelset"
local lib = require "tracks.lib"
track { segments = lib.validation(500), step = 0.5 }
vehicle (ws { speed = 10 })
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
