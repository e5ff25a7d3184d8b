-- The default scene (scenarios/default/case3_kec_fast.lua) with two Manchester wagons 1 in a
-- train{} instead of one vehicle{}: the leading one's reference point at 40 m, the second's at
-- 15 m, 0.3 s (tests/run/test_train.cpp compares each with the default scene's single run at its
-- start).
local c = require "validation.common"
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"
track { segments = lib.manchester_r500(), step = 0.5,
        irregularities = psd { spectrum = "ore_b176_low", seed = 42, wavelengths = { 3, 70 },
                               step = 0.1, fade_in = 0 } }
c.profiles()
c.contact("kec")
train { vehicles = {
  { name = "front", vehicle = wagon { speed = 20, start = 40 } },
  { name = "rear", vehicle = wagon { speed = 20, start = 15 } },
} }
c.abm(20, 1.25e-3)
run { output = { every = 0.01, elements = { "prim_y_ws1_l" } }, duration = 0.3,
      assessment = { safety = true, stability = true, comfort = true, wear = true } }
