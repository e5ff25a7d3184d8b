-- Test study: the study keys of a case (label, role, per-case base) and every figure of
-- plots/rbplot study on the contact wagon of case 3 over 2 m (0.1 s): LUT/KEC pairs (accuracy),
-- references (work precision), a baseline and a variant on another base (effects).
local base = "../../../scenarios/studies/"
local short = { ["run.distance"] = 2 }
local function case(t)
  for k, v in pairs(short) do t[k] = v end
  return t
end
study {
  base = base .. "case3_base.lua",
  cases = {
    case { label = "KEC abm", role = "baseline", ["contact.method"] = "kec" },
    case { ["contact.method"] = "lut", ["contact.flange_stiffness"] = 1e10 },
    case { label = "no bump stops", base = base .. "bases/no_bumpstops.lua",
           ["contact.method"] = "kec" },
    case { ["contact.method"] = "kec", ["solver.method"] = "rk4", ["solver.step"] = 5e-4 },
    case { ["contact.method"] = "lut", ["solver.method"] = "rk4", ["solver.step"] = 5e-4 },
    case { ["contact.method"] = "kec", ["solver.method"] = "dopri5", ["solver.rtol"] = 1e-7,
           ["solver.atol"] = 1e-7, role = "reference" },
    case { ["contact.method"] = "kec", ["solver.method"] = "dopri5", ["solver.rtol"] = 1e-8,
           ["solver.atol"] = 1e-8, role = "reference_check" },
  },
  repeats = 1,
  jobs = 2,
}
