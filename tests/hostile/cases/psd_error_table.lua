-- hostile: expect="psd_error_table.lua:6: track.irregularities (psd): alignment: error called with a table value"
-- error({}) inside a PSD function.
track {
  segments = { tangent { length = 400 } },
  irregularities = psd { spectrum = "user", channels = { "alignment" }, alignment = function(om)
    error({})
  end },
}
