-- hostile: args="check-result result.h5 --exit-code 0 --t-end nan" forge=plain timeout=30
-- hostile: expect="--t-end nan: the end time must be a finite number >= 0"
-- Issue 47: CLI11's NonNegativeNumber lets NaN through (no comparison holds for NaN).
return nil
