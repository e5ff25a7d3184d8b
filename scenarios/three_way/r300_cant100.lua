-- The trial's scenario of issue 34 (item 7), rebuilt for the three-way comparison
-- (docs/three_way.md): Manchester wagon 1 in steady flange contact on an R = 300 m curve with
-- 100 mm cant, ORE B176 high irregularities, 20.9 m/s. The trial found the KEC's flanging wheel
-- switching between tread and two-point contact every 2-3 output samples (Y 5 to 53 kN, std
-- 15.3 kN, a 37 Hz peak in Q) where the LUT's scatter was a third of that with the same means.
-- The trial's file is not in the repository; everything below that the issue does not state is
-- an ASSUMPTION:
--   * layout: 20 m tangent, 60 m clothoid with a linear cant ramp to 100 mm (1.7 mm/m), 300 m of
--     R = 300 m left curve with 100 mm cant (V^2/R = 1.46 m/s^2, cant deficiency 0.80 m/s^2 =
--     122 mm with 1.5 m between the rail centres); the whole wagon is in the full curve from
--     s ~ 102 m (leading wheelset) on;
--   * irregularities: ORE B176 high, seed 42, band 3-70 m, step 0.1 m (the paper's case-3 synthesis
--     with the "high" class instead of "low"), faded in over the default 20 m;
--   * profiles, friction and creep law as the paper's cases (S1002 on 60E1 at 1:40, B = 1360 mm,
--     G = 1435 mm, r0 = 0.46 m, Polach, mu = 0.2364; validation/common.lua);
--   * contact: only keys every method accepts, so `--set contact.method=lut|elastic` switches it:
--     KEC with its defaults dhat = 0.5 mm, dbar = 1 mm (paper section 2.4), LUT with K = 1e10
--     N/m^1.5, D = K/100 (the validation setting), elastic with its Hertz constants
--     (docs/elastic_contact.md); the constraint methods with the default consistent normal forces;
--   * solver: the paper's ABM at 0.25 ms (the validation cases' step at 20 m/s, common.lua);
--   * output every 2 ms (Nyquist 250 Hz): the trial's 10 ms sampling (Nyquist 50 Hz) is taken
--     from it by keeping every 5th sample (docs/three_way.md), so a switching faster than 50 Hz
--     can be told from its alias.
local common = require "validation.common"
track {
  segments = {
    tangent    { length = 20 },
    transition { length = 60, radius = 300, side = "left", cant = 0.100 },
    curve      { length = 300, radius = 300, side = "left", cant = 0.100 },
  },
  step = 0.5,
  irregularities = psd { spectrum = "ore_b176_high", seed = 42, wavelengths = { 3, 70 },
                         step = 0.1 },
}
common.profiles()
contact { method = "kec", creep = "polach", mu = 0.2364 }
vehicle (require "vehicles.manchester_wagon1" { speed = 20.9 })
common.abm(20.9)
run { output = { every = 0.002 } }
