track {
  segments = {
    tangent { length = 30 },
    curve { length = 40, radius = 5 },
  },
}
