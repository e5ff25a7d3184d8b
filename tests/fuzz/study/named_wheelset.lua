-- Named parameters of the single wheelset (elements and bodies, no groups), and of the wagon as
-- another case's base.
study {
  base = "base.lua",
  cases = {
    { ["vehicle.elements.prim_y_l.stiffness"] = 2e6, ["vehicle.bodies.ws.mass"] = 1800 },
    { ["vehicle.elements.load_r.preload"] = 4e4, ["contact.mu"] = 0.3 },
    { base = "wagon.lua", ["vehicle.groups.primary_lateral.damping"] = 0,
      ["profiles.refined_tables"] = true },
  },
}
