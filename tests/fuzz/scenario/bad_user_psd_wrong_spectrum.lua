track {
  segments = { tangent { length = 300 } },
  irregularities = psd {
    spectrum = "ore_b176_lo",
    vertical = function(omega) return 1e-7 end,
  },
}
