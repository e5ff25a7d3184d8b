track { segments = { tangent { length = 100 } } }
vehicle {
  speed = 10,
  bodies = {
    body { name = "ws", kind = "wheelset", mass = -1, inertia = { 1, 0, 1 } },
    body { name = "car", kind = "carbody", mass = 1000, inertia = { 1, 1 } },
  },
  elements = {
    spring_damper { name = "k", from = "car", to = "ws", direction = "q", stiffnes = 1 },
    bumpstop { name = "b", from = "car", to = "ws", table = { 0.025, 0 } },
  },
}
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
