-- hostile: env=RAILBENCH_LUA_SECONDS:3
-- hostile: expect="endless_psd.lua:8:"
-- hostile: expect="endless loop?"
-- A user PSD function that never returns.
track {
  segments = { tangent { length = 400 } },
  irregularities = psd { spectrum = "user", channels = { "alignment" }, alignment = function(om)
    while true do end
  end },
}
