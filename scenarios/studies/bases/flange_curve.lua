-- Base of scenarios/studies/flange_stiffness.lua: the set-up of the hard case
-- scenarios/hard/lut_stiff_flange.lua (the Manchester wagon at 15 m/s into an R = 200 m curve
-- without cant, ORE B176 high irregularities, seed 42: the leading outer flange is reached at
-- t ~ 1 s and stays loaded), 6 s, with a contact block that both methods accept (switch with
-- --set contact.method / contact.flange_stiffness). ASSUMPTIONS as stated in the hard case: on
-- the paper's case-3 track our S1002/60E1 LUT never reaches its flange (docs/studies.md), so the
-- flange stiffness has no effect there; this sharper, rougher track makes it work.
local hard = require "hard.lib"
local common = require "validation.common"
hard.curve_track(200, { irregularities = "ore_b176_high" })
common.profiles()
common.contact("study")
vehicle (require "vehicles.manchester_wagon1" { speed = 15 })
common.abm(20)
run { duration = 6, output = { every = 0.01 } }
