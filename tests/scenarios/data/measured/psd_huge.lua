-- A user PSD off by hundreds of orders of magnitude: refused at check.
track {
  segments = { tangent { length = 200 } },
  irregularities = psd {
    spectrum = "user",
    alignment = function(omega) return 1e300 end,
  },
}
