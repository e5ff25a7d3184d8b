-- hostile: args="tables {case} --out nnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnn/t.h5"
-- hostile: expect="--out: cannot create the folder of"
-- hostile: expect="File name too long"
-- hostile: expect="nothing was run"
-- hostile: timeout=30
-- A folder name longer than the system allows: refused before the tables are built, by name,
-- not as an internal error.
track { segments = { tangent { length = 50 } } }
