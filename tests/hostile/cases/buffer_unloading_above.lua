-- hostile: expect="buffer_unloading_above.lua:10: train.connections 'a-b'.buffers: the unloading force 50000 N at stroke 0.05 m exceeds the loading force 0 N there"
-- An unloading curve above the loading curve between the unloading curve's own points (at the
-- loading curve's knee, 0.05 m): a buffer that gives back more than it takes. Only the unloading
-- points were compared, so this passed.
local wagon = require "vehicles.manchester_wagon1"
track { segments = { tangent { length = 400 } } }
train { vehicles = { { name = "a", vehicle = wagon { speed = 20, start = 60 } },
                     { name = "b", vehicle = wagon { speed = 20, start = 35 } } },
  connections = { { front = "a", rear = "b", front_end = -12.5, rear_end = 12.5,
    buffers = { loading = { { 0, 0 }, { 0.05, 0 }, { 0.1, 2e5 } },
                unloading = { { 0, 0 }, { 0.1, 1e5 } }, spacing = 1.75, height = 1.06 },
    draw_gear = { stiffness = 1e7, height = 1.06 } } } }
contact { method = "kec" }
run { duration = 1 }
