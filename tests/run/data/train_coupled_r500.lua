-- Two Manchester wagons 1 coupled by buffers and a slack-free draw gear (scenarios/train/
-- couplings.lua, ASSUMPTIONS) at a prescribed 20 m/s through the paper's R = 500 m curve on
-- perfect track (tests/run/test_train_connections.cpp compares each wagon's steady curving with
-- the single wagon's). The buffer faces stand 30 mm apart at the start: entering the curve
-- the inner buffers close by up to about 25 mm (the car bodies' relative yaw times half the
-- buffer spacing), so they touch only lightly.
local c = require "validation.common"
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"
local couplings = require "train.couplings"
track { segments = lib.manchester_r500(), step = 0.5 }
c.profiles()
c.contact("kec")
train {
  vehicles = {
    { name = "front", vehicle = wagon { speed = 20, start = 40 } },
    { name = "rear", vehicle = wagon { speed = 20, start = 14.97 } },
  },
  connections = { couplings.screw("front", "rear", { slack = 0.03 }) },
}
c.abm(20, 1.25e-3)
run { output = { every = 0.01 }, duration = 13 }
