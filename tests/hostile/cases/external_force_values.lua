-- hostile: expect="external_force_values.lua:16: element 'g1' (external_force): unknown body 'cra' in 'body' (did you mean 'car'?)"
-- hostile: expect="external_force_values.lua:17: element 'prim_x_ws1_l' (external_force): duplicate element name"
-- hostile: expect="external_force_values.lua:18: element 'g3' (external_force): the point 'at' must lie within 100 m"
-- hostile: expect="external_force_values.lua:20: element 'g4' (external_force): table: t must be strictly increasing (t[3] = 1 after t[2] = 1)"
-- hostile: expect="external_force_values.lua:22: element 'g5' (external_force): table: s[2] must be finite, got"
-- hostile: expect="external_force_values.lua:22: element 'g5' (external_force): table: F[3] must be in [-1e+08, 1e+08] N, got 1e+09"
-- hostile: expect="external_force_values.lua:23: element 'g6' (external_force): table: needs at least 2 points"
-- Values of external forces that only the compiled vehicle can judge (bodies, names, tables): the
-- body misspelt, a name another element has, a point 1 km off the body, tables out of order,
-- with a NaN and with a force of 1 GN, a table of one point. Table problems name the table's line.
local c = require "validation.common"
track { segments = { tangent { length = 300 } } }
c.profiles() c.contact("kec")
local v = require "vehicles.manchester_wagon1" { speed = 20, start = 20 }
local e = v.elements
e[#e + 1] = external_force { name = "g1", body = "cra", direction = { 0, 1, 0 }, value = 1e3 }
e[#e + 1] = external_force { name = "prim_x_ws1_l", body = "car", direction = { 0, 1, 0 }, value = 1e3 }
e[#e + 1] = external_force { name = "g3", body = "car", at = { 0, 1e3, 0 }, direction = { 0, 1, 0 }, value = 1e3 }
e[#e + 1] = external_force { name = "g4", body = "car", direction = { 0, 1, 0 }, law = "table",
  table = { { 0, 0 }, { 1, 5e3 }, { 1, 6e3 } } }
e[#e + 1] = external_force { name = "g5", body = "car", direction = { 0, 1, 0 }, law = "table", over = "distance",
  table = { { 0, 0 }, { 0 / 0, 5e3 }, { 2, 1e9 } } }
e[#e + 1] = external_force { name = "g6", body = "car", direction = { 0, 1, 0 }, law = "table", table = { { 0, 1e3 } } }
vehicle (v)
