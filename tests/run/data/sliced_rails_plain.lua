-- sliced_rails_common.lua without slices: the prismatic rail rails/60e1_a.txt.
require "sliced_rails_common" (nil, 2)
