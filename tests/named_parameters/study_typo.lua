-- A study whose keys name a group, an element and a body that do not exist (a comment naming
-- one of them, "vehicle.bodies.cat.mass", is not its line).
study {
  base = "wagon.lua",
  matrix = {
    ["vehicle.groups.primary_longitudnal.stiffness"] = { 1e7, 2e7 },
    ["vehicle.speed"] = { 10, 20 },
  },
  cases = {
    { ["vehicle.elements.prim_x_ws1_q.stiffness"] = 1e7 },
    { ['vehicle.bodies.cat.mass'] = 33000 },
  },
}
