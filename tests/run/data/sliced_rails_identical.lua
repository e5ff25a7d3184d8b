-- sliced_rails_common.lua on slices that are all the same rail, alternately from two files of the
-- same content (rails/60e1_a.txt, rails/60e1_b.txt): every blend between them is the rail itself.
local a, b = "rails/60e1_a.txt", "rails/60e1_b.txt"
local slices = { { s = 20, rail = a }, { s = 35, rail = b }, { s = 41.5, rail = a },
                 { s = 50, rail = b }, { s = 62, rail = b }, { s = 70, rail = a } }
require "sliced_rails_common" ({ left = slices, right = slices }, 2)
