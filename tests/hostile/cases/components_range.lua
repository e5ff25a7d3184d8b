-- hostile: expect="components_range.lua:5: track.irregularities (psd): components must be <= 100000"
-- help and the track validator agree on the largest number of cosines.
track {
  segments = { tangent { length = 400 } },
  irregularities = psd { spectrum = "ore_b176_low", components = 200000 },
}
