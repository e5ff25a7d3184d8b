-- hostile: args="assess result.h5" forge=short_assessment exit=0 timeout=30
-- hostile: expect="not assessed" expect="replaced /assessment" reject="nan" reject="NaN"
-- An /assessment of 3 samples: no window of the safety assessment fits. The quantity is marked
-- "not assessed"; no NaN value or margin is written or printed.
return nil
