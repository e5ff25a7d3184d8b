-- Track-only run for the plot tests (tests/plots/test_plots.py): a tangent, a clothoid and a
-- canted left curve with ORE B176 low irregularities. 3 km, so that the Welch estimate of the
-- synthesised irregularities can be held to its target PSD per octave (a 500 m record scatters
-- by about 30 % in its longest octave).
track {
  segments = {
    tangent    { length = 1500 },
    transition { length = 100, radius = 1000, side = "left", cant = 0.05 },
    curve      { length = 1400, radius = 1000, side = "left", cant = 0.05 },
  },
  step = 0.5,
  irregularities = psd { spectrum = "ore_b176_low", seed = 1, wavelengths = { 3, 70 }, step = 0.1 },
}
