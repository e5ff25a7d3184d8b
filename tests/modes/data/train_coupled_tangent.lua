-- Two Manchester wagons 1 (scenarios/vehicles/manchester_wagon1.lua) on a tangent, S1002 on 60E1
-- at 1:40 with KEC and Polach (scenarios/validation/common.lua), coupled by side buffers and a
-- slack-free screw coupling (scenarios/train/couplings.lua, its stated assumptions) with the
-- buffer faces touching: the train whose modes tests/modes/test_train_modes.cpp compares with one
-- wagon's.
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
local couplings = require "train.couplings"
track { segments = { tangent { length = 400 } }, step = 0.5 }
c.profiles()
c.contact("kec")
train {
  vehicles = {
    { name = "w1", vehicle = wagon { speed = 30, start = 80 } },
    { name = "w2", vehicle = wagon { speed = 30, start = 55 } },
  },
  connections = { couplings.screw("w1", "w2", { slack = 0 }) },
}
c.abm(20, 1.25e-3)
run { output = { every = 0.01 }, duration = 1 }
