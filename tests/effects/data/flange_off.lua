-- Hostile input of tests/effects: flange contact cannot be switched off (line 8).
local common = require "validation.common"
local lib = require "tracks.lib"
track { segments = lib.validation(500), step = 0.5 }
common.profiles()
common.contact("kec")
vehicle (require "vehicles.single_wheelset" { speed = 10 })
run { output = { every = 0.01 }, effects = { flange_contact = false } }
