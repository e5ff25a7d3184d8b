-- lut at R = 1000 m (lut_jump_common.lua).
require "lut_jump_common" { radius = 1000, method = "lut" }
