-- Paper section 5.3 (Tables 7, 12-16) on our model: Manchester wagon, R = 500 m, V = 20 m/s,
-- 500 m with ORE B176 low irregularities (case 3), KEC and LUT with every integrator; 5 repeats
-- (CPU time as the median, evaluation counts exact). Long: run explicitly with
--   ./wb study scenarios/studies/efficiency_case3.lua
-- Fixed steps: 0.25 ms instead of the paper's 1 ms (stability of the free-spin creep mode, see
-- scenarios/validation/common.lua); LUT flange stiffness K from the paper's Table 3 with
-- D = K/100.
local cases = {}
local solvers = {
  { ["solver.method"] = "rk4", ["solver.step"] = 2.5e-4 },
  { ["solver.method"] = "abm", ["solver.step"] = 2.5e-4 },
}
for _, tol in ipairs({ 1e-4, 1e-5, 1e-6 }) do
  for _, m in ipairs({ "dopri5", "bdf" }) do
    solvers[#solvers + 1] = { ["solver.method"] = m, ["solver.rtol"] = tol, ["solver.atol"] = tol,
                              ["solver.max_step"] = 1e-3 }
  end
end
for _, s in ipairs(solvers) do
  local kec = { ["contact.method"] = "kec" }
  for k, v in pairs(s) do kec[k] = v end
  if s["solver.method"] == "bdf" then kec["contact.normal_forces"] = "consistent" end
  cases[#cases + 1] = kec
  for _, K in ipairs({ 1e9, 1e10, 1e11, 1e12, 7.075e13 }) do
    local lut = { ["contact.method"] = "lut", ["contact.flange_stiffness"] = K }
    for k, v in pairs(s) do lut[k] = v end
    if s["solver.method"] == "bdf" then lut["contact.normal_forces"] = "consistent" end
    cases[#cases + 1] = lut
  end
end

study {
  base = "case3_base.lua",
  cases = cases,
  repeats = 5,
}
