-- hostile: expect="memory budget of 1024 MiB"
-- hostile: timeout=700 env=RAILBENCH_LUA_SECONDS:600
-- The script catches "not enough memory" and ends at the limit: the host must not abort in its
-- own API calls afterwards (references to the PSD function).
-- The time budget is raised so that the memory budget stops the script under the sanitizers too
-- (a clang ASan build takes about 2 minutes to fill 1 GiB here; the Release build seconds).
local hold = {}
pcall(function() while true do hold[#hold + 1] = string.rep("y", 1 << 20) .. #hold end end)
track {
  segments = { tangent { length = 400 } },
  irregularities = psd { spectrum = "user", channels = { "alignment" },
    alignment = function(om) return 1e-7 end },
}
