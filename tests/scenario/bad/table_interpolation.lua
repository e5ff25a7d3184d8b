track { segments = { tangent { length = 100 } } }
contact {
  method = "lut",
  table_interpolation = "bilinear",
}
