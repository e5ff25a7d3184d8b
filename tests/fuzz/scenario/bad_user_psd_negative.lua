track {
  segments = { tangent { length = 300 } },
  irregularities = psd {
    spectrum = "user",
    alignment = function(omega) return -1e-7 end,
  },
}
