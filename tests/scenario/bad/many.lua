-- several problems at once: all must be reported together
track {
  segments = {
    tangent { length = 0 },
    curve { length = 40, raduis = 300 },
  },
  stepp = 0.5,
}
solver { method = "rk5" }
run { distance = -1 }
vehicle (require "vehicles.manchester_wagon1" { speed = 10 })
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
