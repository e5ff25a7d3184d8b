-- hostile: args="check-result result.h5 --exit-code 0" forge=huge_declared timeout=30
-- hostile: expect="/contact/ws1/left/Q declares 100000000000 values" expect="more than the file can hold"
-- Issue 47: the NaN/Inf scan of check-result read every dataset into memory from its declared
-- size: std::bad_alloc, exit 3. Now refused, exit 1.
return nil
