-- hostile: args="assess result.h5" forge=huge_declared timeout=30
-- hostile: expect="/contact/ws1/left/Q declares 100000000000 values" expect="more than the file can hold"
-- Issue 47: a dataset declares 1e11 samples (800 GB) in a file of a few kB; the reader allocated
-- from the declared size and ended in std::bad_alloc, exit 3. Now refused, exit 1.
return nil
