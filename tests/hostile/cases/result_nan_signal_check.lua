-- hostile: args="check-result result.h5 --exit-code 0" forge=nan_signal exit=2 timeout=30
-- hostile: expect="NaN/Inf in /bodies/ws1/y" reject="\"problems\": []"
-- A result with one NaN sample in a run's output: check-result's own check (no NaN/Inf in any
-- dataset, README) finds it and names the dataset; the file does not pass (exit 2), never exit 0
-- nor an internal error.
return nil
