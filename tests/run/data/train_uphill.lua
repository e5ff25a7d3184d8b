-- Two Manchester wagons 1 coasting up a 2 % gradient (a level tangent, a 50 m transition to the
-- gradient, then 300 m at 2 %), perfect track, KEC, Polach: their motion along the track is a
-- state without traction or resistance, so the slope alone decelerates them
-- (tests/run/test_train_connections.cpp compares with the hand calculation).
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
local couplings = require "train.couplings"
track { segments = { tangent { length = 20 }, transition { length = 50, gradient = 0.02 },
                     tangent { length = 300, gradient = 0.02 } }, step = 0.5 }
c.profiles()
c.contact("kec")
train {
  vehicles = {
    { name = "w1", vehicle = wagon { speed = 20, start = 120 } },
    { name = "w2", vehicle = wagon { speed = 20, start = 95 } },
  },
  connections = { couplings.screw("w1", "w2", { slack = 0 }) },
  longitudinal = {},
}
c.abm(20, 1.25e-3)
run { output = { every = 0.01 }, duration = 2 }
