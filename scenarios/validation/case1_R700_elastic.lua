-- Paper section 5.2, case 1 with the elastic contact method: single wheelset at V = 10 m/s,
-- R = 700 m (Fig. 16-17, Table 5). Set-up and assumptions in common.lua; the three-way comparison
-- with KEC and LUT in docs/three_way.md.
require("validation.common").case1(700, "elastic")
