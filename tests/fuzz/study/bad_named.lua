-- Override paths that name nothing: typos of a group, element, body, block and key.
study {
  base = "wagon.lua",
  matrix = { ["vehicle.groups.primary_longitudnal.stiffness"] = { 1e7 } },
  cases = {
    { ["vehicle.elements.prim_x_ws9_l.damping"] = 1e4 },
    { ["vehicle.bodies.kar.mass"] = 1 },
    { ["solver.mehtod"] = "rk4" },
    { ["nosuch.block"] = 1, ["vehicle.elements[1].x"] = 2, ["."] = 0, ["a..b"] = 1 },
  },
}
