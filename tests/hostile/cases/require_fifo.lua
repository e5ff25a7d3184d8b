-- hostile: fifo=pipe.lua
-- hostile: expect="require_fifo.lua:6:"
-- hostile: expect="not a regular file (a FIFO)"
-- hostile: timeout=30
-- A FIFO would block forever.
require "pipe"
