track {
  segments = { tangent { length = 30 }
  step = 0.5,
}
