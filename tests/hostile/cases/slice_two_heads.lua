-- hostile: expect="nose_and_wing.txt:"
-- hostile: expect="rises again by"
-- hostile: expect="a second rail head or a step would be cut away"
-- hostile: expect="max_slope"
-- A slice holding a crossing nose and a wing rail in one profile, its flangeway's walls steeper
-- than the reader's default 10: keeping the longest run alone would drop the nose.
local wagon = require "vehicles.manchester_wagon1"
profiles { r0 = 0.46,
  rail_slices = { right = { { s = 0, rail = "nose_and_wing.txt" },
                            { s = 400, rail = "nose_and_wing.txt" } } } }
track { segments = { tangent { length = 300 } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 20 })
