-- Three wagons on the default scene's track (the paper's case 3: 100 m tangent, 50 m clothoid,
-- R = 500 m without cant, ORE B176 low irregularities 3-70 m seed 42, S1002 on 60E1 at 1:40,
-- Polach with mu = 0.2364) at 20 m/s: two Manchester wagons 1 on KEC and, behind them, a generic
-- two-axle wagon (scenarios/vehicles/two_axle_wagon.lua, stated assumptions) on elastic
-- multi-point contact. Each vehicle stands at its own vehicle start, the leading wagon's
-- reference point at 60 m; the gaps between the outermost wheelsets are ASSUMPTIONS (no
-- connections in this scene: the vehicles do not interact; scenarios/train/loco_braking_r500.lua
-- couples its vehicles with buffers and draw gear).
-- Each vehicle's outputs and assessment: /vehicles/<name>.
local c = require "validation.common"
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"
local two_axle = require "vehicles.two_axle_wagon"
track { segments = lib.manchester_r500(), step = 0.5,
        irregularities = psd { spectrum = "ore_b176_low", seed = 42, wavelengths = { 3, 70 },
                               step = 0.1, fade_in = 20 } }
c.profiles()
c.contact("kec")
train { vehicles = {
  { name = "wagon1", vehicle = wagon { speed = 20, start = 60 } },
  -- 25 m behind (ASSUMPTION: a wagon length over buffers of 25 m): the Manchester wagon's outer
  -- wheelsets are 21.56 m apart, which leaves 3.44 m between the last wheelset of one and the
  -- first of the next.
  { name = "wagon2", vehicle = wagon { speed = 20, start = 35 } },
  -- The two-axle wagon (wheelbase 9 m) 19 m behind the second (ASSUMPTION).
  { name = "two_axle", vehicle = two_axle { speed = 20, start = 16 },
    contact = { method = "elastic", creep = "polach", mu = 0.2364 } },
} }
c.abm(20, 2.5e-4)
run { output = { every = 0.01 }, duration = 2,
      assessment = { safety = true, stability = true, comfort = true, wear = true } }
