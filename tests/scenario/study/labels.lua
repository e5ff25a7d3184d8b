-- Study keys inside cases: label, base, role; labels made from the overrides otherwise.
study {
  base = "base_a.lua",
  matrix = { ["solver.method"] = { "rk4", "bdf" } },
  cases = {
    { ["contact.method"] = "lut", ["contact.flange_stiffness"] = 1e10 },
    { ["contact.method"] = "kec", label = "KEC", role = "reference" },
    { base = "base_b.lua", label = "other base" },
  },
}
