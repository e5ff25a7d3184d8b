-- nose_slcs.lua with its slices listed one by one: the same 21 files at s = 50 m + u
-- (tests/run/test_slice_files.cpp).
local wagon = require "vehicles.manchester_wagon1"
local slices = {
  { s = 49.9, rail = "cross_nose/nose_1.prr", dz = -0.05 },
  { s = 49.91, rail = "cross_nose/nose_2.prr", dz = -0.05 },
  { s = 49.92, rail = "cross_nose/nose_3.prr", dz = -0.05 },
  { s = 49.93, rail = "cross_nose/nose_4.prr", dz = -0.05 },
  { s = 49.94, rail = "cross_nose/nose_5.prr", dz = -0.05 },
  { s = 49.95, rail = "cross_nose/nose_6.prr", dz = -0.05 },
  { s = 49.96, rail = "cross_nose/nose_7.prr", dz = -0.05 },
  { s = 49.97, rail = "cross_nose/nose_8.prr", dz = -0.05 },
  { s = 49.98, rail = "cross_nose/nose_9.prr", dz = -0.05 },
  { s = 49.99, rail = "cross_nose/nose_10.prr", dz = -0.05 },
  { s = 50.0, rail = "cross_nose/nose_11.prr", dz = -0.05 },
  { s = 50.01, rail = "cross_nose/nose_12.prr", dz = -0.05 },
  { s = 50.02, rail = "cross_nose/nose_13.prr", dz = -0.05 },
  { s = 50.03, rail = "cross_nose/nose_14.prr", dz = -0.05 },
  { s = 50.04, rail = "cross_nose/nose_15.prr", dz = -0.05 },
  { s = 50.05, rail = "cross_nose/nose_16.prr", dz = -0.05 },
  { s = 50.06, rail = "cross_nose/nose_17.prr", dz = -0.05 },
  { s = 50.07, rail = "cross_nose/nose_18.prr", dz = -0.05 },
  { s = 50.08, rail = "cross_nose/nose_19.prr", dz = -0.05 },
  { s = 50.09, rail = "cross_nose/nose_20.prr", dz = -0.05 },
  { s = 50.1, rail = "cross_nose/nose_21.prr", dz = -0.05 } }
track { segments = { tangent { length = 300 } } }
profiles { wheel = "s1002", back_to_back = 1.360, gauge = 1.435, r0 = 0.46, inclination = 0,
           extra_rails = { right = { { name = "nose", slices = slices } } } }
contact { method = "elastic" }
vehicle (wagon { speed = 20, start = 30 })
solver { method = "abm", step = 5e-4 }
