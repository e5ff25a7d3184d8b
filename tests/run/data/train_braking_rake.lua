-- A rake of three Manchester wagons 1 braking on level tangent track: the leading wagon brakes
-- with 60 kN (ramped in over 0.5 s from t = 0.2 s), the two behind it are unbraked and push it
-- through their buffers (tests/run/test_train_connections.cpp checks the in-train forces against the
-- decelerating masses). Perfect track, KEC, Polach; the buffer and draw-gear data are the
-- ASSUMPTIONS of scenarios/train/couplings.lua.
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
local couplings = require "train.couplings"
track { segments = { tangent { length = 400 } }, step = 0.5 }
c.profiles()
c.contact("kec")
train {
  vehicles = {
    { name = "w1", vehicle = wagon { speed = 20, start = 80 },
      traction = { { 0, 0 }, { 0.2, 0 }, { 0.7, -60e3 } } },
    { name = "w2", vehicle = wagon { speed = 20, start = 55 } },
    { name = "w3", vehicle = wagon { speed = 20, start = 30 } },
  },
  connections = {
    couplings.screw("w1", "w2", { slack = 0 }),
    couplings.screw("w2", "w3", { slack = 0 }),
  },
  longitudinal = {},
}
c.abm(20, 1.25e-3)
run { output = { every = 0.005 }, duration = 3 }
