--@set track.segments[99999999999999999999999].length=1
track { segments = { tangent { length = 100 } } }
