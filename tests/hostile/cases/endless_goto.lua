-- hostile: env=RAILBENCH_LUA_SECONDS:3
-- hostile: expect="endless_goto.lua:6:"
-- hostile: expect="endless loop?"
-- goto loop.
::top::
goto top
