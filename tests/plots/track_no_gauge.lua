-- Track-only run for the plot tests: irregularities with the gauge channel left out, whose
-- figures must still be drawn (the channel shows as disabled).
track {
  segments = { tangent { length = 200 }, curve { length = 300, radius = 800, side = "right" } },
  step = 0.5,
  irregularities = psd { spectrum = "ore_b176_low", seed = 2, wavelengths = { 3, 70 },
                         channels = { "alignment", "vertical", "cross_level" } },
}
