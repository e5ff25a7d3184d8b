track { segments = { tangent { length = 30 } } }
track { segments = { tangent { length = 40 } } }
