-- hostile: args="assess result.h5" forge=nan_assessment timeout=30
-- hostile: expect="/assessment/safety/ws1/left/Y holds NaN at sample 400 of 801"
-- hostile: reject="replaced /assessment"
-- Issue 47: one NaN sample in a signal under /assessment made assess write NaN values and
-- margins (exit 0). Now refused, exit 1, and the file is not rewritten.
return nil
