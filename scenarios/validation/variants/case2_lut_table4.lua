-- Paper section 5.2, case 2 (LUT), variant: the Manchester wagon with the paper's Table 4 elements
-- alone, without the anti-roll bars of the benchmark data that ../case2_lut.lua carries.
-- docs/validation.md compares both with the paper's Table 6.
require("validation.common").wagon("lut", false, false)
