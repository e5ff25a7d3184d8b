-- The paper's case 3 (Manchester wagon, R = 500 m, V = 20 m/s, ORE B176 low irregularities, seed
-- 42; scenarios/validation/common.lua) with switches, for the base scenarios of the studies in
-- this folder (bases/*.lua):
--   require "studies.wagon" { irregularities = false, bumpstops = false }
-- Options (default: the full case 3 model, the same as case3_base.lua):
--   irregularities = false    no track irregularities (the paper's case 2 track)
--   tangent = true            a 500 m tangent instead of the R = 500 m curve (no curving: the
--                             flanges are not reached)
--   bumpstops = false         vehicle without its lateral bump stops
--   series_dampers = false    plain dampers instead of the series dampers (manchester_wagon1.lua)
--   element_outputs = true    deflection and force of all 50 elements written (run.output.elements)
-- The contact block accepts both methods (switch with --set contact.method=lut).
local common = require "validation.common"
local lib = require "tracks.lib"

return function(o)
  o = o or {}
  local irr = nil
  if o.irregularities ~= false then
    -- fade_in = 0: case 3 as the paper and scenarios/validation/common.lua have it (no ramp).
    irr = psd { spectrum = "ore_b176_low", seed = 42, wavelengths = { 3, 70 }, step = 0.1,
                fade_in = 0 }
  end
  local segments = o.tangent and { tangent { length = 500 } } or lib.manchester_r500()
  track { segments = segments, step = 0.5, irregularities = irr }
  common.profiles()
  common.contact("study")
  local v = require "vehicles.manchester_wagon1" {
    speed = 20, bumpstops = o.bumpstops, series_dampers = o.series_dampers }
  vehicle (v)
  common.abm(20)
  local output = { every = 0.01 }
  if o.element_outputs then
    local names = {}
    for i, e in ipairs(v.elements) do names[i] = e.name end
    output.elements = names
  end
  run { output = output }
end
