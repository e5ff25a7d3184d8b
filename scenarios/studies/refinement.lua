-- Paper section 5.5 (Tables 9-11, 17-18, Fig. 26): default vs refined contact tables
-- (profiles.refined_tables: the finer LUT/KEC grids of Tables 9-10) on case 3 (500 m), prescribed
-- spin, the paper's section 5.3 solver settings (lib.paper_solvers: RK4 and ABM at 1 ms, dopri5
-- and BDF at 1e-4 ... 1e-6 without a largest step), 3 repeats:
--   like for like with the paper: the tables interpolated linearly (section 5.5), KEC and LUT
--   (K = 1e10, Tables 17-18); our cubic / bicubic tables (the default) as the variant beside it;
--   Table 11 (and Table 7 for comparison): LUT with the Hertzian K = 7.075e13, default and
--   refined, at the tolerances the paper's Table 11 needed (ode15s 1e-6, ode45 1e-7) and RK4 /
--   ABM at 1 ms, linear, and its adaptive pair with the cubic tables (with KEC at dopri5 1e-7 for
--   the KEC/LUT ratio).
-- About 6 minutes on one core.
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
local function add(...)
  for _, refined in ipairs({ false, true }) do
    cases[#cases + 1] = lib.merge(spin, { ["profiles.refined_tables"] = refined }, ...)
  end
end
for _, interpolation in ipairs({ "linear", "cubic" }) do
  for _, s in ipairs(solvers) do
    for _, contact in ipairs({ lib.kec(), lib.lut(1e10) }) do
      add(contact, s, lib.interpolation(interpolation))
    end
  end
end
-- Table 11: K = 7.075e13 with and without refinement.
local bdf6, dopri7 = lib.adaptive("bdf", 1e-6, 0), lib.adaptive("dopri5", 1e-7, 0)
for _, s in ipairs({ bdf6, dopri7, lib.fixed("rk4", h), lib.fixed("abm", h) }) do
  add(lib.lut(7.075e13), s, lib.interpolation("linear"))
end
for _, interpolation in ipairs({ "linear", "cubic" }) do
  add(lib.kec(), dopri7, lib.interpolation(interpolation))
end
for _, s in ipairs({ bdf6, dopri7 }) do add(lib.lut(7.075e13), s, lib.interpolation("cubic")) end

study {
  base = "case3_base.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = cases,
  repeats = 3,
}
