-- Hard case 1 with the elastic contact method: the set-up of lut_stiff_flange.lua (Manchester
-- wagon 1 at 15 m/s into R = 200 m without cant, ORE B176 high irregularities, seed 42; the
-- leading wheelset's outer flange hits the rail at t ~ 1.0 s) with elastic multi-point contact
-- instead of the LUT. The LUT run with the paper's stiff flange (K = 7.075e13 N/m^1.5) stops at
-- t = 1.04 s with every integrator: its tread constraint would have to pull (wheel lift). The
-- elastic method's flange stiffness is Hertz's from the local curvatures of the flange contact
-- (no K to choose), its tread may lift: the run goes on to its end (docs/elastic_contact.md).
local hard = require "hard.lib"
hard.curve_track(200, { irregularities = "ore_b176_high" })
hard.profiles()
contact { method = "elastic", creep = "polach", mu = hard.MU_PAPER }
vehicle (require "vehicles.manchester_wagon1" { speed = 15 })
solver { method = "dopri5" }
run { duration = 3, output = { every = 0.01 },
      assessment = { safety = true, stability = true, comfort = true, wear = true } }
