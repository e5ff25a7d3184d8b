-- Paper section 5.2, case 1 (KEC): single wheelset, V = 10 m/s, R = 700 m (Table 5). Set-up and
-- assumptions in common.lua; results beside the paper's in docs/validation.md.
require("validation.common").case1(700, "kec")
