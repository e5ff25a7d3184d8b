-- The three-way comparison of issue 34 item 7 (docs/three_way.md): the paper's cases 1-3, the
-- hard cases with the stiff flange, the sharp curve and the wheel climb, and the trial's
-- R = 300 m / 100 mm cant scenario, each with the constraint methods KEC and LUT and with elastic multi-point contact.
-- Every method of a scenario runs with the same integrator and step, so the evaluation counts are
-- equal and the CPU times compare the cost of one evaluation:
--   * validation cases: their own solver (ABM 0.2 ms for case 1 at 10 m/s, 0.25 ms for cases 2
--     and 3; validation/common.lua), the shipped case*_{kec,lut,elastic}.lua files;
--   * hard cases and the trial: ABM 0.25 ms (with the default exponential treatment of the stiff
--     spin and series-damper components), the step with which the elastic stiff-flange case runs
--     to its end (docs/hard_cases.md).
-- The methods are switched with --set contact.method on bases whose contact block has only the keys
-- every method accepts (the elastic method rejects the constraint-only keys).
--   ./wb study scenarios/studies/three_way.lua --out out/three_way
--   plots/rbplot three-way out/three_way       (tables and figures; ./wb studies --only three_way)
-- One run per case (repeats = 1): CPU times on a shared machine scatter by 10-40 %; the
-- instruction counts of `rbplot effects-instructions` (run by ./wb studies) do not.
local METHODS = { "kec", "lut", "elastic" }
local ABM = { ["solver.method"] = "abm", ["solver.step"] = 2.5e-4 }
local cases = {}
local function add(label, base, overrides)
  local c = { label = label, base = base }
  for k, v in pairs(overrides or {}) do c[k] = v end
  cases[#cases + 1] = c
end
local function with(t, extra)
  local out = {}
  for k, v in pairs(t) do out[k] = v end
  for k, v in pairs(extra or {}) do out[k] = v end
  return out
end

-- Paper case 1 (single wheelset, 10 m/s), every radius of Table 5.
for _, R in ipairs({ 300, 500, 700, 900 }) do
  for _, m in ipairs(METHODS) do
    add(("case1 R=%d | %s"):format(R, m), ("../validation/case1_R%d_%s.lua"):format(R, m))
  end
end
-- Paper cases 2 (smooth) and 3 (ORE B176 low), wagon at 20 m/s, R = 500 m.
for _, c in ipairs({ 2, 3 }) do
  for _, m in ipairs(METHODS) do
    add(("case%d | %s"):format(c, m), ("../validation/case%d_%s.lua"):format(c, m))
  end
end
-- Case 3 with an adaptive integrator (dopri5, rtol = atol = 1e-6, no largest step): whether the
-- elastic contact's stiffness costs steps (the evaluation counts of the three methods).
for _, m in ipairs(METHODS) do
  add("case3 dopri5 1e-6 | " .. m, ("../validation/case3_%s.lua"):format(m),
      { ["solver.method"] = "dopri5", ["solver.rtol"] = 1e-6, ["solver.atol"] = 1e-6 })
end
-- Hard case: the stiff flange (R = 200 m, 15 m/s, ORE B176 high). The LUT with the paper's
-- Hertz flange K = 7.075e13 (hard/lut_stiff_flange.lua) and with the validation K = 1e10.
add("stiff_flange | kec", "../hard/elastic_stiff_flange.lua", with(ABM, { ["contact.method"] = "kec" }))
add("stiff_flange | lut", "../hard/lut_stiff_flange.lua", ABM)
add("stiff_flange | lut K=1e10", "../hard/elastic_stiff_flange.lua",
    with(ABM, { ["contact.method"] = "lut" }))
add("stiff_flange | elastic", "../hard/elastic_stiff_flange.lua", ABM)
-- Hard case: the sharp curve (R = 150 m, 16 m/s, smooth, sustained two-point contact).
for _, m in ipairs(METHODS) do
  add("sharp_curve | " .. m, "../hard/sharp_curve.lua", with(ABM, { ["contact.method"] = m }))
end
-- Hard case: wheel climb (R = 100 m, 5 m/s, dry rail mu = 0.5): the leading outer wheel's Y/Q near
-- the Nadal limit of the 70 degree flank (0.95).
for _, m in ipairs(METHODS) do
  add("wheel_climb | " .. m, "../hard/wheel_climb.lua", with(ABM, { ["contact.method"] = m }))
end
-- The elastic wheelset's bouncing on its flank in this case, with dopri5 at 1e-6: the model's or
-- the integrator's?
add("wheel_climb | elastic dopri5 1e-6", "../hard/wheel_climb.lua",
    { ["contact.method"] = "elastic", ["solver.rtol"] = 1e-6, ["solver.atol"] = 1e-6 })
-- The trial's scenario (R = 300 m, 100 mm cant, ORE B176 high, 20.9 m/s).
for _, m in ipairs(METHODS) do
  add("trial_r300 | " .. m, "../three_way/r300_cant100.lua", { ["contact.method"] = m })
end
-- The constraint methods' scatter on the trial with an adaptive integrator (dopri5, rtol = atol =
-- 1e-6, no largest step): a property of the model, not of the ABM step, if it stays.
for _, m in ipairs({ "kec", "lut" }) do
  add("trial_r300 | " .. m .. " dopri5 1e-6", "../three_way/r300_cant100.lua",
      { ["contact.method"] = m, ["solver.method"] = "dopri5", ["solver.rtol"] = 1e-6,
        ["solver.atol"] = 1e-6 })
end

study {
  base = "../validation/case3_kec.lua",
  -- Full results: the per-patch series (two-point contact, flange patches) are read.
  output = "full",
  cases = cases,
  repeats = 1,
  jobs = 1,
}
