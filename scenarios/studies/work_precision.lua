-- Work-precision: what accuracy costs in CPU time, on the paper's case 3 (Manchester wagon,
-- R = 500 m, V = 20 m/s, ORE B176 low irregularities) for KEC and LUT (K = 1e10): every
-- integrator over a range of tolerances (dopri5, BDF, IDA: rtol = atol = 1e-3 ... 1e-8, largest
-- step 1 ms) or steps (RK4, ABM: 1, 0.5, 0.25, 0.125, 0.0625 ms), each
-- compared with a REFERENCE of the same contact model: BDF at rtol 1e-9 / atol 1e-10 on the
-- refined contact tables (profiles.refined_tables). The reference's own error is measured by a
-- second reference at 10x tighter tolerances (role "reference_check"); the figures grey out
-- errors below it. A third run, the reference's settings on the default tables (role
-- "reference_same_tables"), splits the error: against it, the cases' errors are integration
-- errors only (study_work_precision_integration*.png); its own difference to the reference is
-- the error of the default contact tables (a vertical line in study_work_precision*.png: no
-- default-table case gets below it, whatever its tolerance).
--   ./wb study scenarios/studies/work_precision.lua           (out/work_precision/)
-- Outputs: study_work_precision.csv (per case: max and RMS error of the wheelsets' lateral
-- displacement y [mm] and yaw [mrad], and the wheels' normal force Q and lateral creep force
-- [kN], over the reference's output times, all wheelsets; the reference_check row is the
-- reference's error; column `against` says which reference), study_work_precision.png (max
-- error vs CPU time, log-log), study_work_precision_rms.png (RMS),
-- study_work_precision_integration{,_rms}.png (against the same-tables reference),
-- study_cost.png/.csv, study_failures.csv.
--
-- Distance: the whole 500 m track (tangent, transition and 350 m of curve with flange contact)
-- unless DISTANCE is set below (e.g. 200: the curve entry only; ~2.5x cheaper).
local DISTANCE = 500
-- Models: KEC and LUT (K = 1e10) with the free wheelset spin (our default model; fixed steps are
-- stable up to about 0.27 ms (ABM) / 0.5 ms (RK4), larger steps appear as failed cases), and KEC
-- with the prescribed spin (contact.wheelset_spin = "prescribed", the paper's 1 ms fixed steps;
-- a different model, so it has its own reference). IDA only for the free-spin models; for the
-- free-spin KEC also dopri5 and BDF without a largest step (max_step = 0).
local lib = require "studies.lib"
local run = { ["run.distance"] = DISTANCE }
local models = {
  { contact = lib.kec(), spin = lib.spin(false), adaptive = { "dopri5", "bdf", "ida" },
    unlimited = true },
  { contact = lib.lut(1e10), spin = lib.spin(false), adaptive = { "dopri5", "bdf", "ida" } },
  { contact = lib.kec(), spin = lib.spin(true), adaptive = { "dopri5", "bdf" } },
}
local cases = {}
for _, mdl in ipairs(models) do
  local contact, spin = mdl.contact, mdl.spin
  for _, m in ipairs({ "rk4", "abm" }) do
    for _, h in ipairs({ 1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5 }) do
      cases[#cases + 1] = lib.merge(contact, lib.fixed(m, h), spin, run)
    end
  end
  for _, m in ipairs(mdl.adaptive) do
    for _, tol in ipairs({ 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8 }) do
      cases[#cases + 1] = lib.merge(contact, lib.adaptive(m, tol, 1e-3), spin, run)
    end
  end
  -- Without the paper's 1 ms largest step: what the error control alone chooses.
  if mdl.unlimited then
    for _, m in ipairs({ "dopri5", "bdf" }) do
      for _, tol in ipairs({ 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8 }) do
        cases[#cases + 1] = lib.merge(contact, lib.adaptive(m, tol, 0), spin, run)
      end
    end
  end
  local refined = { ["profiles.refined_tables"] = true }
  local ref = lib.merge(contact, lib.adaptive("bdf", 1e-9, 1e-3, 1e-10), spin, run, refined)
  ref.role = "reference"
  cases[#cases + 1] = ref
  local check = lib.merge(contact, lib.adaptive("bdf", 1e-10, 1e-3, 1e-11), spin, run, refined)
  check.role = "reference_check"
  cases[#cases + 1] = check
  local same = lib.merge(contact, lib.adaptive("bdf", 1e-9, 1e-3, 1e-10), spin, run)
  same.role = "reference_same_tables"
  cases[#cases + 1] = same
end

study {
  base = "case3_base.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = cases,
  repeats = 1,
}
