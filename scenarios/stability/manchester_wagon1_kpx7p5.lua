-- Manchester wagon 1 (scenarios/vehicles/manchester_wagon1.lua) with the primary longitudinal
-- stiffness Kpx lowered to 7.5e6 N/m per spring ([T4]: 31391e3), i.e. the primary yaw stiffness
-- 2 Kpx b^2 (b = 1 m) of every wheelset to its bogie lowered to the same fraction. ASSUMPTION: a
-- design variant for the stability study of docs/stability.md (the critical speed against the
-- primary yaw stiffness), not a vehicle of the paper. A vehicle file: the stability commands put
-- it on their default scene, e.g.
--   ./wb critical-speed scenarios/stability/manchester_wagon1_kpx7p5.lua --contact kec
return function(opts)
  opts = opts or {}
  opts.primary_longitudinal_stiffness = 7.5e6
  return (require "vehicles.manchester_wagon1")(opts)
end
