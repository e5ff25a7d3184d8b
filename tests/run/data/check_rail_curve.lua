-- check_rail_common.lua with the check rail.
require "check_rail_common" (true)
