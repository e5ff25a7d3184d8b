-- The study keys of a case: label, role, its own base.
study {
  base = "base.lua",
  cases = {
    { label = "KEC", role = "baseline", ["contact.method"] = "kec" },
    { ["contact.method"] = "lut", ["contact.flange_stiffness"] = 1e10 },
    { label = "wagon", base = "wagon.lua", ["solver.method"] = "abm" },
    { ["solver.method"] = "dopri5", ["solver.rtol"] = 1e-8, ["solver.atol"] = 1e-8,
      role = "reference" },
    { ["solver.method"] = "dopri5", ["solver.rtol"] = 1e-9, ["solver.atol"] = 1e-9,
      role = "reference_check" },
    { ["solver.method"] = "bdf", role = "reference_same_tables", ["solver.max_steps"] = 100 },
  },
  output = "compact",
}
