-- hostile: args="modes {case}"
-- hostile: expect="modes_train_guided.lua: vehicle 'w2' of the train has guided wheelsets: the modes need every vehicle on wheel/rail contact"
-- hostile: expect="nothing was run"
-- reject="internal error"
-- A train with a guided vehicle has no linear stability of its own: refused as the scene's input
-- problem (it once left the command as an internal error).
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 300 } } }
contact { method = "kec" }
train { vehicles = {
  { name = "w1", vehicle = wagon { speed = 20, start = 60 } },
  { name = "w2", vehicle = wagon { speed = 20, start = 35 }, contact = { method = "guided" } },
} }
