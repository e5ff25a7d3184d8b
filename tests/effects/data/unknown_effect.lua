-- Hostile input of tests/effects: an effect name that does not exist (line 8).
local common = require "validation.common"
local lib = require "tracks.lib"
track { segments = lib.validation(500), step = 0.5 }
common.profiles()
common.contact("kec")
vehicle (require "vehicles.single_wheelset" { speed = 10 })
run { output = { every = 0.01 }, effects = { bump_stop = false } }
