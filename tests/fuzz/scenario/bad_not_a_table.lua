track {
  segments = { tangent(30) },
}
