-- Named parameters of  base.
study {
  base = "base.lua",
  cases = {
    { ["vehiclçe.elements.prim_y_l.stiffness-- =ables"] = true },
  },
}
