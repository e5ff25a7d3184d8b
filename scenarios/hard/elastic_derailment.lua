-- Hard case with the elastic contact method: a derailment by flange climb, which the constraint
-- methods cannot simulate (their wheels cannot lift). The leading wheelset of a guided bogie frame
-- (scenarios/vehicles/single_wheelset.lua, paper case 1's set-up) at 5 m/s on the tangent before
-- a left curve of R = 100 m, with dry rail (mu = 0.5, ASSUMPTION).
-- ASSUMPTION: a constant lateral force of 250 kN pushes the wheelset toward the right rail from
-- t = 0, applied at rail level (as a wheel-climb rig applies it, so that it does not tip the
-- wheelset over the rail): a zero-stiffness element whose preload is the force. Against the
-- primary lateral springs and the flange contact it throws the wheelset onto its right flange,
-- the right wheel climbs and the run stops with exit 2 at t = 0.024 s, naming the wheel, the time
-- and the distance (docs/elastic_contact.md, "Lift and derailment").
local hard = require "hard.lib"
hard.curve_track(100, { tangent = 5, transition = 10, curve = 100 })
hard.profiles()
contact { method = "elastic", creep = "polach", mu = 0.5 }
local v = require "vehicles.single_wheelset" { speed = 5 }
v.elements[#v.elements + 1] = spring_damper {
  name = "push", from = "frame", to = "ws", at_from = { 1.28, 0.5, -0.6 }, at_to = { 0, 0, -0.46 },
  direction = "y", stiffness = 0, damping = 0, preload = 250e3 }
vehicle (v)
solver { method = "dopri5" }
run { duration = 4, output = { every = 0.01 } }
