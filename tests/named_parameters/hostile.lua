-- Hostile groups written in the scenario: an empty name, a body, a dotted group name, a number.
track { segments = { tangent { length = 100 } } }
vehicle (require "vehicles.tiny" { groups = {
  empty_name = { "" },
  body_member = { "ws" },
  ["a.b"] = { "spring_l" },
  not_a_name = { 42 },
  everything = { "*" },
  dotted = { "dotted.name" },
} })
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
