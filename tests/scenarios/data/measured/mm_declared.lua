-- The same file with its unit declared; the 100 m track is covered (s = 0 .. 100 m).
track {
  segments = { tangent { length = 100 } },
  irregularities = measured { file = "track_in_mm.csv", unit = "mm" },
}
