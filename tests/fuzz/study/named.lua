-- Named parameters: a group, an element and a body of the wagon.
study {
  base = "wagon.lua",
  matrix = { ["vehicle.groups.primary_longitudinal.stiffness"] = { 1e7, 2e7 },
             ["vehicle.speed"] = { 10, 20 } },
  cases = {
    { ["vehicle.elements.prim_x_ws1_l.damping"] = 1e4 },
    { ["vehicle.bodies.car.mass"] = 33000, label = "heavy" },
  },
}
