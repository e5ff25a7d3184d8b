-- hostile: expect="globals_metatable_swapped.lua:6:"
-- hostile: expect="attempt to call a nil value (global 'tangnet')"
-- Removing the globals' metatable only loses the "did you mean" hints; a nil constructor still
-- fails with a location.
setmetatable(_G, nil)
tangnet { length = 1 }
