-- Paper section 5.2, case 1 with the elastic contact method: single wheelset at V = 10 m/s,
-- R = 500 m (Fig. 16-17, Table 5). Set-up and assumptions in common.lua.
require("validation.common").case1(500, "elastic")
