-- Two Manchester wagons 1 joined by a central coupler link (no side buffers) at a prescribed
-- 20 m/s through the paper's R = 500 m curve on perfect track: the link's angle to each car body
-- is the curve's geometry (tests/run/test_train_connections.cpp). Coupler data are ASSUMPTIONS
-- of a central coupler (pivots 1.5 m behind the headstocks, 10 MN/m, stops at 0.2 rad), the slack
-- wide enough that the link carries no force at the prescribed speed.
local c = require "validation.common"
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"
track { segments = lib.manchester_r500(), step = 0.5 }
c.profiles()
c.contact("kec")
train {
  vehicles = {
    { name = "front", vehicle = wagon { speed = 20, start = 40 } },
    { name = "rear", vehicle = wagon { speed = 20, start = 14.97 } },
  },
  connections = {
    { front = "front", rear = "rear", front_end = -12.5, rear_end = 12.5,
      coupler = { stiffness = 1e7, slack = 0.05, height = 1.0, pivot = 1.5, angle_stop = 0.2,
                  stop_stiffness = 1e6 } },
  },
}
c.abm(20, 1.25e-3)
run { output = { every = 0.01 }, duration = 13 }
