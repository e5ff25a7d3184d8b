-- hostile: args="check-result result.h5 --exit-code 0" forge=fifo_store timeout=20
-- hostile: expect="/track@stored_in" expect="tracks/0123456789abcdef.h5: is a FIFO"
-- Issue 47: /track@stored_in names a FIFO; the track store was opened without checking that it
-- is a regular file, and check-result hung in the open. Now refused, exit 1.
return nil
