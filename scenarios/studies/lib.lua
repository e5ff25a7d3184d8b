-- Helpers of the study files in this folder: solver settings and case tables.
--   local lib = require "studies.lib"
local M = {}

-- A new table with the entries of every argument (later ones win).
function M.merge(...)
  local out = {}
  for _, t in ipairs({ ... }) do
    for k, v in pairs(t) do out[k] = v end
  end
  return out
end

-- Fixed-step solver settings: { method = "abm", step = 2.5e-4 }. The studies measure what the
-- paper's explicit methods do at the paper's steps (solver.stiff = "explicit": no exponential
-- treatment of the stiff components), also beyond the stability limit of the free spin's creep
-- mode (which `check` refuses otherwise), so they accept such a step explicitly.
function M.fixed(method, step)
  return { ["solver.method"] = method, ["solver.step"] = step, ["solver.stiff"] = "explicit",
           ["solver.accept_unstable_step"] = true }
end

-- Fixed-step settings with the stiff components integrated exponentially (solver.stiff, the
-- default of a scenario; docs/integrators.md).
function M.exponential(method, step)
  return { ["solver.method"] = method, ["solver.step"] = step, ["solver.stiff"] = "exponential" }
end

-- The normal forces solved together with the creep forces at every evaluation (the scenario
-- default; the study bases state the paper's lagged coupling).
function M.consistent() return { ["contact.normal_forces"] = "consistent" } end

-- Adaptive solver settings with rtol = atol = tol (the paper's ode45 / ode15s settings) and a
-- largest step max_step (0: none). The study bases state the paper's lagged normal forces
-- (validation/common.lua, contact "study"), with which the generated tables of docs/studies.md
-- were made; BDF and IDA solve the normal forces together with the creep forces
-- (contact.normal_forces = "consistent"): with the lagged normal forces of the explicit methods
-- its Newton iteration sees a non-smooth right-hand side (docs/contact_dynamics.md).
-- solver.max_steps = 1e5: at tight tolerances the default limit (500 steps per 10 ms output
-- interval) stops BDF with "too much work" in the flange contact phases; a work limit, not an
-- accuracy setting, so it is not shown in the case labels.
function M.adaptive(method, tol, max_step, atol)
  local s = { ["solver.method"] = method, ["solver.rtol"] = tol, ["solver.atol"] = atol or tol,
              ["solver.max_step"] = max_step, ["solver.max_steps"] = 100000 }
  if method == "bdf" or method == "ida" then s["contact.normal_forces"] = "consistent" end
  return s
end

-- The paper's efficiency settings (section 5.3, Tables 7, 11-18): RK4 and ABM at the fixed step
-- h, dopri5 (ode45) and BDF (ode15s) at each tolerance of tols WITHOUT a largest step
-- (solver.max_step = 0). The paper states its 1 ms largest step only for the accuracy comparison
-- (section 5.4); its efficiency counts cannot come from capped runs: its KEC with ode45 at 1e-4
-- makes 38 719 evaluations over 25 s, about 6 450 steps of 6 evaluations, 3.9 ms on average,
-- where a 1 ms cap alone asks for 25 000 steps.
function M.paper_solvers(h, tols)
  local solvers = { M.fixed("rk4", h), M.fixed("abm", h) }
  for _, m in ipairs({ "dopri5", "bdf" }) do
    for _, tol in ipairs(tols) do
      solvers[#solvers + 1] = M.adaptive(m, tol, 0)
    end
  end
  return solvers
end

-- The paper's accuracy settings (section 5.4, Table 8, Fig. 24): ode45 and ode15s (dopri5, BDF)
-- at rtol = atol = 1e-6 with the 1 ms largest step stated there. Their cases carry the label
-- suffix ACCURACY_LABEL.
M.ACCURACY_LABEL = " (paper Table 8 setting: 1 ms cap)"
function M.accuracy_solvers()
  return { M.adaptive("dopri5", 1e-6, 1e-3), M.adaptive("bdf", 1e-6, 1e-3) }
end

-- A number as the study labels write it: 1e-06 -> 1e-6, 7.075e+13 -> 7.075e13.
function M.compact(v) return (string.format("%g", v):gsub("e%+?(%-?)0*(%d)", "e%1%2")) end

-- KEC and LUT (every K of Table 3) at the accuracy settings, labelled as such (the model and
-- solver as the default labels write them, with ACCURACY_LABEL appended).
function M.accuracy_cases(extra)
  local cases = M.stiffness_cases(M.accuracy_solvers(), extra)
  for _, c in ipairs(cases) do
    local model = c["contact.method"] == "kec" and "KEC"
                  or "LUT K=" .. M.compact(c["contact.flange_stiffness"])
    c.label = string.format("%s %s tol=%s hmax=1ms%s", model, c["solver.method"],
                            M.compact(c["solver.rtol"]), M.ACCURACY_LABEL)
  end
  return cases
end

-- Interpolation of the contact tables between their grid points (section 5.5: the paper's
-- tables interpolate linearly; ours default to cubic / bicubic).
function M.interpolation(kind) return { ["contact.table_interpolation"] = kind } end

-- The paper's flange stiffness study (Fig. 23, Tables 12-16): for every solver, KEC and LUT with
-- K = 1e9 ... 7.075e13 N/m^1.5 (Table 3), each merged with the extra overrides.
function M.stiffness_cases(solvers, extra)
  local cases = {}
  for _, s in ipairs(solvers) do
    cases[#cases + 1] = M.merge(M.kec(), s, extra)
    for _, K in ipairs({ 1e9, 1e10, 1e11, 1e12, 7.075e13 }) do
      cases[#cases + 1] = M.merge(M.lut(K), s, extra)
    end
  end
  return cases
end

-- Contact settings: M.kec(), M.lut(K) (D = K/100, the paper's Table 3).
function M.kec() return { ["contact.method"] = "kec" } end
function M.lut(K) return { ["contact.method"] = "lut", ["contact.flange_stiffness"] = K } end

-- The wheelset spin: "free" (a state driven by the creep forces; its creep mode limits fixed
-- steps to about 0.25 ms at 20 m/s) or "prescribed" (V / r0, as in the paper: 1 ms steps work).
-- Returns the override table for a case and the fixed step that goes with it.
function M.spin(prescribed)
  if prescribed then return { ["contact.wheelset_spin"] = "prescribed" }, 1e-3 end
  return {}, 2.5e-4
end

-- The paper's solver settings (section 5.3) for the KEC/LUT cost ratio per integrator
-- (paper_settings.lua, paper_settings_flange.lua): KEC and LUT with the Hertzian flange stiffness
-- K = 7.075e13 N/m^1.5 (Table 3, D = K/100), the prescribed spin, RK4 and ABM at 1 ms, dopri5
-- (ode45) at 1e-6 and 1e-8 and BDF (ode15s) at 1e-6 and 1e-7 (Table 7), each adaptive setting
-- with the 1 ms largest step of the paper's accuracy comparison (section 5.4) and without a cap
-- (solver.max_step = 0: the paper's efficiency settings, as lib.paper_solvers). Labels "<model> | <solver>" pair KEC and LUT.
function M.paper_settings_cases()
  local spin, h = M.spin(true)
  local solvers = { { "RK4 1 ms", M.fixed("rk4", h) }, { "ABM 1 ms", M.fixed("abm", h) } }
  for _, s in ipairs({ { "dopri5", 1e-6 }, { "dopri5", 1e-8 }, { "bdf", 1e-6 }, { "bdf", 1e-7 } }) do
    local name = string.format("%s %g", s[1], s[2])
    solvers[#solvers + 1] = { name .. ", 1 ms cap", M.adaptive(s[1], s[2], 1e-3) }
    solvers[#solvers + 1] = { name .. ", no cap", M.adaptive(s[1], s[2], 0) }
  end
  local cases = {}
  for _, s in ipairs(solvers) do
    for _, m in ipairs({ { "KEC", M.kec() }, { "LUT K=7.075e13", M.lut(7.075e13) } }) do
      cases[#cases + 1] = M.merge({ label = m[1] .. " | " .. s[1] }, m[2], s[2], spin)
    end
  end
  return cases
end

return M
