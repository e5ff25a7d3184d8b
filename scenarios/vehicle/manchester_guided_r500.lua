-- Issue 5 check scenario: the Manchester wagon on the paper's R = 500 m track (case 2 layout) at
-- 20 m/s with its wheelsets following the track kinematically (no wheel/rail contact yet): car
-- body and bogies respond to the curve entry through the suspension.
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"

track { segments = lib.manchester_r500() }
vehicle (wagon { speed = 20 })
-- Guided wheelsets asked for by name: without a contact{} block a vehicle with wheelsets is an
-- error, so that a forgotten contact model never runs silently.
contact { method = "guided" }
solver { method = "abm", step = 1e-3 }
run { output = { every = 0.01, elements = { "sec_z_bogie1_l", "prim_z_ws1_l" }, body_accelerations = true },
      -- Guided wheelsets have no wheel/rail forces: comfort and stability only.
      assessment = { stability = true, comfort = true } }
