-- A file in millimetres declared (by default) as metres: check refuses it with the CSV's
-- file:line instead of a failure inside the contact solve.
track {
  segments = { tangent { length = 100 } },
  irregularities = measured { file = "track_in_mm.csv" },
}
