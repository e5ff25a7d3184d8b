-- Paper section 5.2, case 2 with the elastic contact method: Manchester wagon 1, V = 20 m/s,
-- R = 500 m, no irregularities (Table 6). Set-up and assumptions in common.lua; the comparison
-- with KEC and LUT in docs/elastic_contact.md.
require("validation.common").wagon("elastic", false)
