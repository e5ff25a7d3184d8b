-- check_rail_common.lua without the check rail.
require "check_rail_common" (false)
