-- Paper section 5.5 (Tables 9-11, 17-18, Fig. 26): default vs refined contact tables
-- (profiles.refined_tables: the finer LUT/KEC grids of Tables 9-10) for KEC and LUT (K = 1e10,
-- Tables 17-18) with every integrator, on case 3 (500 m), 5 repeats; and LUT with the Hertzian
-- K = 7.075e13 refined at the tolerances the paper's Table 11 needed (ode15s 1e-6, ode45 1e-7).
--   ./wb study scenarios/studies/refinement.lua                 (out/refinement/)
-- Figures and tables: study_cost.png/.csv (Fig. 26; the CSV has each case's table build time
-- and size: table_build_time_s, table_bytes), study_tables.png (Tables 9-10: build time and
-- memory, default vs refined), study_failures.csv, study_accuracy_lut_vs_kec.csv/.png.
-- Wheelset spin prescribed and 1 ms fixed steps, as efficiency_case3.lua (the same switch):
local PRESCRIBED_SPIN = true

local lib = require "studies.lib"
local spin, h = lib.spin(PRESCRIBED_SPIN)
local solvers = lib.paper_solvers(h, { 1e-4, 1e-5, 1e-6 })
local cases = {}
for _, s in ipairs(solvers) do
  for _, contact in ipairs({ lib.kec(), lib.lut(1e10) }) do
    for _, refined in ipairs({ false, true }) do
      cases[#cases + 1] = lib.merge(contact, s, spin, { ["profiles.refined_tables"] = refined })
    end
  end
end
-- Table 11 (and Table 7 for comparison): K = 7.075e13 with and without refinement.
for _, s in ipairs({ lib.adaptive("bdf", 1e-6, 1e-3), lib.adaptive("dopri5", 1e-7, 1e-3) }) do
  for _, refined in ipairs({ false, true }) do
    cases[#cases + 1] = lib.merge(lib.lut(7.075e13), s, spin,
                                  { ["profiles.refined_tables"] = refined })
  end
end

study {
  base = "case3_base.lua",
  cases = cases,
  repeats = 5,
}
