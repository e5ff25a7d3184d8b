-- sliced_rails_common.lua with a second rail on the right side: from s = 60 m to 100 m the
-- running rail is lowered from 0 to 2 mm while a second rail of the same profile ("nose", present
-- from s = 55 m on) rises from 2 mm below to level. The wheels move from the one to the
-- other where the two are level, at s = 80 m.
local a = "rails/60e1_a.txt"
local running = { { s = 60, rail = a }, { s = 100, rail = a, dz = -0.002 } }
local nose = { { s = 55, rail = a, dz = -0.002 }, { s = 60, rail = a, dz = -0.002 },
               { s = 100, rail = a }, { s = 200, rail = a } }
require "sliced_rails_common" ({ right = running }, 5.5,
                               { right = { { name = "nose", slices = nose } } })
