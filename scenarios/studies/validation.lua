-- The paper's validation cases (section 5.2, Tables 5 and 6, Fig. 16-22) as shipped in
-- scenarios/validation/ and their set-up variants, each run unchanged (its own solver: ABM 0.2 ms
-- for case 1, 0.25 ms for cases 2 and 3), and cases 2 and 3 also with dopri5 at rtol = atol = 1e-6. The steady-curving
-- values, the Eq. (33) difference between KEC and LUT on case 3 and the cost table of
-- docs/validation.md come from this study (plots/rbplot validation-tables; ./wb studies --only
-- validation). One case at a time, 3 repeats: the CPU times are medians.
--   ./wb study scenarios/studies/validation.lua             (out/validation/)
local lib = require "studies.lib"
local cases = {}
for _, R in ipairs({ 300, 500, 700, 900 }) do
  for _, m in ipairs({ "kec", "lut" }) do
    cases[#cases + 1] = { label = ("case 1 R=%d %s"):format(R, m:upper()),
                          base = ("../validation/case1_R%d_%s.lua"):format(R, m) }
  end
end
-- The set-up variants beside them (scenarios/validation/variants/): case 1 with the frame centred
-- at the wheelset, case 2 with the paper's Table 4 elements alone (no anti-roll bars).
for _, R in ipairs({ 300, 500, 700, 900 }) do
  for _, m in ipairs({ "kec", "lut" }) do
    cases[#cases + 1] = { label = ("case 1 R=%d %s centred frame"):format(R, m:upper()),
                          base = ("../validation/variants/case1_R%d_%s_centred.lua"):format(R, m) }
  end
end
for _, m in ipairs({ "kec", "lut" }) do
  cases[#cases + 1] = { label = ("case 2 %s Table 4 alone"):format(m:upper()),
                        base = ("../validation/variants/case2_%s_table4.lua"):format(m) }
end
for _, c in ipairs({ 2, 3 }) do
  for _, m in ipairs({ "kec", "lut" }) do
    local base = ("../validation/case%d_%s.lua"):format(c, m)
    cases[#cases + 1] = { label = ("case %d %s"):format(c, m:upper()), base = base }
    cases[#cases + 1] = lib.merge({ label = ("case %d %s dopri5 1e-6"):format(c, m:upper()),
                                    base = base }, lib.adaptive("dopri5", 1e-6))
  end
end

study {
  base = "../validation/case3_kec.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = cases,
  repeats = 3,
  jobs = 1,
}
