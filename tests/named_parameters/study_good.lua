-- A study sweeping a group, an element and a body by name.
study {
  base = "wagon.lua",
  matrix = {
    ["vehicle.groups.primary_longitudinal.stiffness"] = { 1e7, 2e7 },
  },
  cases = {
    { ["vehicle.elements.prim_x_ws1_l.damping"] = 1e4 },
    { ["vehicle.bodies.car.mass"] = 33000 },
  },
}
