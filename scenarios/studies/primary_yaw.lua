-- A physics sweep: how the primary yaw stiffness of the Manchester wagon trades its running
-- stability on tangent track against speed. Primary longitudinal stiffness Kpx (the 8 springs
-- that give each wheelset its yaw stiffness to the bogie frame, 2 Kpx b^2 with b = 1 m; named
-- group primary_longitudinal of scenarios/vehicles/manchester_wagon1.lua) x speed, on the hunting
-- hard case's track (scenarios/hard/hunting.lua: 3 km tangent, ORE B176 low irregularities scaled
-- by 0.1 as a small disturbance, KEC, Polach, dopri5), 8 s per case. Per case:
--   y_ws1_max           largest |lateral displacement| of the leading wheelset [m]
--   hunting_amplitude   half peak-to-peak of that displacement over the last 2 s [m]: a limit
--                       cycle (hunting) keeps it up, below the critical speed it stays at the
--                       irregularities' level
--   y_over_q_max        largest Y/Q of any wheel (EN 14363 sliding mean, /assessment)
--   linear_critical_speed  where the least damped hunting mode of the linearised vehicle loses
--                       its damping (workbench/stability, docs/stability.md), the same for every
--                       speed of one stiffness
-- Values of Kpx: 7.5, 15 MN/m (the stability method study's), the published 31.391 MN/m ([T4])
-- and twice it (ASSUMPTION: a stiffer design variant for the trade-off, not a published one).
--   ./wb study scenarios/studies/primary_yaw.lua           (out/primary_yaw/)
study {
  base = "../hard/hunting.lua",
  matrix = {
    ["vehicle.groups.primary_longitudinal.stiffness"] = { 7.5e6, 15e6, 31.391e6, 62.782e6 },
    ["vehicle.speed"] = { 40, 50, 60, 70, 80, 90 },
  },
  cases = { { ["run.duration"] = 8 } },
  metrics = {
    { name = "y_ws1_max", signal = "/bodies/ws1/y", stat = "max_abs" },
    { name = "hunting_amplitude", signal = "/bodies/ws1/y", stat = "half_peak_to_peak",
      along = "time", from = 6, to = 8 },
    { name = "y_over_q_max", kind = "assessment", quantity = "y_over_q" },
    { name = "linear_critical_speed", kind = "linear_critical_speed", speeds = { 20, 120, 21 } },
  },
}
