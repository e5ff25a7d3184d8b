-- The file covers 100 m of a 300 m track: an error unless beyond = "zero" is chosen.
track {
  segments = { tangent { length = 300 } },
  irregularities = measured { file = "track_in_mm.csv", unit = "mm" },
}
