-- hostile: expect="external_force_keys.lua:23: vehicle.elements[51] (external_force): unknown key 'vlaue' (did you mean 'value'?)"
-- hostile: expect="external_force_keys.lua:24: vehicle.elements[52] (external_force): rate applies to law = \"ramp\" only (law is \"constant\")"
-- hostile: expect="external_force_keys.lua:25: vehicle.elements[53] (external_force): give rate or duration, not both"
-- hostile: expect="external_force_keys.lua:26: vehicle.elements[54] (external_force): law = \"ramp\" needs value [N]"
-- hostile: expect="external_force_keys.lua:27: vehicle.elements[55] (external_force): law = \"table\" needs table"
-- hostile: expect="external_force_keys.lua:28: vehicle.elements[56] (external_force): value must be finite, got"
-- hostile: expect="external_force_keys.lua:29: vehicle.elements[57] (external_force): rate must be > 0 N/s, got -5"
-- hostile: expect="external_force_keys.lua:30: vehicle.elements[58] (external_force): frame: unknown value 'trak' (did you mean 'track'?)"
-- hostile: expect="external_force_keys.lua:31: vehicle.elements[59] (external_force): direction must be a vector of length > 0"
-- hostile: expect="external_force_keys.lua:32: vehicle.elements[60] (external_force): direction must be {x, y, z} of numbers"
-- hostile: expect="external_force_keys.lua:33: vehicle.elements[61] (external_force): over applies to law = \"table\" only (law is \"ramp\")"
-- hostile: expect="external_force_keys.lua:34: vehicle.elements[62] (external_force): missing required key 'body'"
-- hostile: expect="external_force_keys.lua:35: vehicle.elements[63] (external_force): law = \"ramp\" needs rate [N/s] or duration [s]"
-- hostile: expect="external_force_keys.lua:36: vehicle.elements[64] (external_force): law: unknown value 'tabel' (did you mean 'table'?)" reject="table applies to"
-- The keys of external forces, every one wrong in its own way on its own line: each problem is
-- reported where it is written, all at once, and nothing is run; a misspelt law is reported
-- alone (not with the keys of the law it would fall back to).
local c = require "validation.common"
track { segments = { tangent { length = 300 } } }
c.profiles() c.contact("kec")
local v = require "vehicles.manchester_wagon1" { speed = 20, start = 20 }
local e = v.elements
e[#e + 1] = external_force { name = "f1", body = "car", direction = { 0, 1, 0 }, vlaue = 1e3 }
e[#e + 1] = external_force { name = "f2", body = "car", direction = { 0, 1, 0 }, value = 1e3, rate = 5e3 }
e[#e + 1] = external_force { name = "f3", body = "car", direction = { 0, 1, 0 }, law = "ramp", value = 1e3, rate = 5e3, duration = 1 }
e[#e + 1] = external_force { name = "f4", body = "car", direction = { 0, 1, 0 }, law = "ramp", rate = 5e3 }
e[#e + 1] = external_force { name = "f5", body = "car", direction = { 0, 1, 0 }, law = "table" }
e[#e + 1] = external_force { name = "f6", body = "car", direction = { 0, 1, 0 }, value = 0 / 0 }
e[#e + 1] = external_force { name = "f7", body = "car", direction = { 0, 1, 0 }, law = "ramp", value = 1e3, rate = -5 }
e[#e + 1] = external_force { name = "f8", body = "car", direction = { 0, 1, 0 }, frame = "trak", value = 1e3 }
e[#e + 1] = external_force { name = "f9", body = "car", direction = { 0, 0, 0 }, value = 1e3 }
e[#e + 1] = external_force { name = "f10", body = "car", direction = "y", value = 1e3 }
e[#e + 1] = external_force { name = "f11", body = "car", direction = { 0, 1, 0 }, law = "ramp", value = 1e3, duration = 2, over = "distance" }
e[#e + 1] = external_force { name = "f12", direction = { 0, 1, 0 }, value = 1e3 }
e[#e + 1] = external_force { name = "f13", body = "car", direction = { 0, 1, 0 }, law = "ramp", value = 1e3 }
e[#e + 1] = external_force { name = "f14", body = "car", direction = { 0, 1, 0 }, law = "tabel", table = { { 0, 0 }, { 1, 1e3 } } }
vehicle (v)
