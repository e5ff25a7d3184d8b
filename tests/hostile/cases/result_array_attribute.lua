-- hostile: args="check-result result.h5 --exit-code 2" forge=array_attribute exit=2 timeout=30
-- hostile: expect="failure record without failure time"
-- Found with issue 47: /stats@t_reached holds 4096 values; the readers read a numeric attribute
-- into one double, so HDF5 wrote 32 kB over the stack (a crash, or silent corruption). An
-- attribute is now read only when it holds one value: here t_reached is absent, and the checks
-- of a failed run report what they miss (exit 2, the file does not pass).
return nil
