-- hostile: expect="vehicle_start_beyond_track.lua:6: vehicle: the leading body starts at s = 151.28 m, at or beyond the end of the track at 100 m" reject="vehicle_start_beyond_track.lua:8:"
-- vehicle.start beyond the track's end: reported at the vehicle, where the start is given (it was
-- reported at the run { line as a run that would go beyond the track).
track { segments = { tangent { length = 100 } } }
contact { method = "kec" }
vehicle (require "vehicles.single_wheelset" { speed = 10, start = 150 })
solver { method = "abm", step = 2e-4 }
run { duration = 0.1 }
