-- Test scenario: the Manchester wagon file on a straight track (tests/vehicle). fixtures.hpp
-- loads the wagon from here for every vehicle test (speed and start are set per test).
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 200 } } }
vehicle (wagon { speed = 20, start = 20 })
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
