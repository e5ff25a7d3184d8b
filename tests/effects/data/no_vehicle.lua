-- Hostile input of tests/effects: a scene without a vehicle has nothing to simulate.
local lib = require "tracks.lib"
track { segments = lib.validation(500), step = 0.5 }
