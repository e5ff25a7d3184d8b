-- Paper section 5.2, case 3 with the elastic contact method: case 2 with the ORE B176 low
-- irregularities (seed 42). Set-up and assumptions in common.lua; the comparison with KEC and LUT
-- in docs/elastic_contact.md.
require("validation.common").wagon("elastic", true)
