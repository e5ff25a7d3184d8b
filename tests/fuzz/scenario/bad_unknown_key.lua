track {
  segments = {
    tangent { lenght = 30 },
  },
}
