-- hostile: expect="psd_error_line.lua:7: track.irregularities (psd): alignment: bad omega"
-- hostile: reject="psd_error_line.lua:6:"
-- error() inside a PSD function is reported where it was raised, not at the psd{ line.
track {
  segments = { tangent { length = 400 } },
  irregularities = psd { spectrum = "user", channels = { "alignment" }, alignment = function(om)
    if om > 0 then error("bad omega") end
    return 1e-7
  end },
}
