-- Paper section 5.2, case 1 (LUT): single wheelset, V = 10 m/s, R = 500 m (Table 5). Set-up and
-- assumptions in common.lua; results beside the paper's in docs/validation.md.
require("validation.common").case1(500, "lut")
