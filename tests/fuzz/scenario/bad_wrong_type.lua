track {
  segments = {
    tangent { length = 30 },
    curve { length = "forty", radius = 300 },
  },
}
