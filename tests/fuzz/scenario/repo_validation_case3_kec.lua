-- Paper section 5.2, case 3 (KEC): Manchester wagon 1, V = 20 m/s, R = 500 m, ORE B176 low
-- irregularities, seed 42 (Fig. 21-22). Set-up and assumptions in common.lua; results in
-- docs/validation.md.
require("validation.common").wagon("kec", true)
