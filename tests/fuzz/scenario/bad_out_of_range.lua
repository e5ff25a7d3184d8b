track {
  segments = { tangent { length = 30 } },
  step = -0.5,
  rail_inclination = 0.5,
}
