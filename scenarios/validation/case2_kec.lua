-- Paper section 5.2, case 2 (KEC): Manchester wagon 1, V = 20 m/s, R = 500 m, no irregularities
-- (Table 6). Set-up and assumptions in common.lua; results in docs/validation.md.
require("validation.common").wagon("kec", false)
