-- Example study (issue 7): cost of the integrators on the guided Manchester wagon (no wheel/rail
-- contact) over the R = 500 m track. Run: ./build/workbench/app/workbench study THIS_FILE
study {
  base = "../vehicle/manchester_guided_r500.lua",
  -- Full case files: this study's figures and docs read the cases' complete results (the
  -- per-patch series, the track in each file), and it measures what a plain run costs.
  output = "full",
  cases = {
    { ["solver.method"] = "rk4", ["solver.step"] = 1e-3 },
    { ["solver.method"] = "abm", ["solver.step"] = 1e-3 },
    { ["solver.method"] = "dopri5", ["solver.rtol"] = 1e-6, ["solver.atol"] = 1e-6, ["solver.max_step"] = 1e-3 },
    { ["solver.method"] = "bdf", ["solver.rtol"] = 1e-6, ["solver.atol"] = 1e-6, ["solver.max_step"] = 1e-3 },
  },
  repeats = 1,
}
