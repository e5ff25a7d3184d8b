-- A locomotive-like leading vehicle and three wagons braking in the paper's R = 500 m curve
-- (docs/trains.md). Track: the paper's case 3 (100 m tangent, 50 m clothoid, R = 500 m left
-- without cant; ORE B176 low irregularities 3-70 m, seed 42, faded in over 20 m), S1002 on 60E1 at
-- 1:40, KEC, Polach with mu = 0.2364.
--
-- Vehicles (ASSUMPTIONS, no locomotive data were at hand): the leading vehicle is the Manchester
-- wagon 1 with a 60 t car body (inertias scaled with the mass) on the wagon's bogies and
-- suspension, standing for a locomotive; the wagons are Manchester wagons 1. 25 m over buffers
-- with the buffer faces 1 mm apart at the start and 2 mm draw-gear slack (the static equilibrium
-- on the irregular track turns the car bodies by a fraction of a millimetre at the headstocks, and
-- a connection loaded at the start is refused), buffers and screw couplings of
-- scenarios/train/couplings.lua (ASSUMPTIONS there).
--
-- Motion: the train enters at 20 m/s; the leading vehicle brakes electrically with 120 kN, built
-- up linearly from t = 1 s to t = 3 s, the wagons are unbraked: they push the leading vehicle,
-- and the compressive forces turn against the curve. Running resistance of every vehicle in the
-- Davis form with the coefficients of a 45 t coach (ASSUMPTION: a = 650 N, b = 15 N s/m,
-- c = 3 N s^2/m^2).
local c = require "validation.common"
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"
local couplings = require "train.couplings"
track { segments = lib.manchester_r500(), step = 0.5,
        irregularities = psd { spectrum = "ore_b176_low", seed = 42, wavelengths = { 3, 70 },
                               step = 0.1, fade_in = 20 } }
c.profiles()
c.contact("kec")

local function locomotive(opts)
  local v = wagon(opts)
  for _, b in ipairs(v.bodies) do
    if b.name == "car" then
      local scale = 60000 / b.mass
      b.mass = 60000
      b.inertia = { b.inertia[1] * scale, b.inertia[2] * scale, b.inertia[3] * scale }
    end
  end
  return v
end

local resistance = { a = 650, b = 15, c = 3 }
train {
  vehicles = {
    { name = "loco", vehicle = locomotive { speed = 20, start = 85 }, resistance = resistance,
      traction = { { 0, 0 }, { 1, 0 }, { 3, -120e3 } } },
    { name = "wagon1", vehicle = wagon { speed = 20, start = 59.999 }, resistance = resistance },
    { name = "wagon2", vehicle = wagon { speed = 20, start = 34.998 }, resistance = resistance },
    { name = "wagon3", vehicle = wagon { speed = 20, start = 9.997 }, resistance = resistance },
  },
  connections = {
    couplings.screw("loco", "wagon1", { slack = 0.002 }),
    couplings.screw("wagon1", "wagon2", { slack = 0.002 }),
    couplings.screw("wagon2", "wagon3", { slack = 0.002 }),
  },
  longitudinal = {},
}
c.abm(20, 6.25e-4)  -- the heavier car body's series dampers need <= 0.87 ms
run { output = { every = 0.01 }, duration = 12,
      assessment = { safety = true, comfort = true } }
