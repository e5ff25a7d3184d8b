-- Test scenario: the Manchester wagon with the paper's Table 4 elements alone (no anti-roll bars).
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 200 } } }
vehicle (wagon { speed = 20, start = 20, anti_roll_bar = false })
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
