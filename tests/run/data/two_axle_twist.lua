-- A train of two loaded two-axle wagons (scenarios/vehicles/two_axle_wagon.lua with the car body's
-- mass raised to 38 t, an ASSUMPTION: wheel loads near 100 kN as in a loaded wagon) at rest-like
-- speed on the default scene's track with ORE B176 low irregularities; the rear wagon's leading
-- wheelset at s = 108.5 m, where the rails' vertical irregularities twist the wagon by about 1 mm
-- per metre. Its static equilibrium loads every wheel with 90-110 kN.
local c = require "validation.common"
local lib = require "tracks.lib"
local two_axle = require "vehicles.two_axle_wagon"
track { segments = lib.manchester_r500(), step = 0.5,
        irregularities = psd { spectrum = "ore_b176_low", seed = 42, wavelengths = { 3, 70 },
                               step = 0.1, fade_in = 20 } }
c.profiles()
c.contact("kec")
local function loaded(start)
  local v = two_axle { speed = 20, start = start }
  v.bodies[1].mass = 38000
  return v
end
train { vehicles = {
  { name = "front", vehicle = loaded(116) },
  { name = "rear", vehicle = loaded(104) },
} }
c.abm(20, 2.5e-4)
run { output = { every = 0.01 }, duration = 0.05 }
