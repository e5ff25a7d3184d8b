-- hostile: expect="profile_long_name.lua:5: profiles: wheel: file"
-- hostile: expect="not found"
-- A 5000-character profile file name: the file system refuses it; an input error, not exit 3.
track { segments = { tangent { length = 100 } } }
profiles { wheel = string.rep("w", 5000) .. ".prw" }
