track { segments = { tangent { length = 1e308 } } }
