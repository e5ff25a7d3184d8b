-- hostile: args="check-result result.h5 --exit-code 0 --t-end inf" forge=plain timeout=30
-- hostile: expect="--t-end inf: the end time must be a finite number >= 0"
return nil
