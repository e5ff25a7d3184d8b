-- kec at R = 300 m (lut_jump_common.lua).
require "lut_jump_common" { radius = 300, method = "kec" }
