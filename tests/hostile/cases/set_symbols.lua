-- hostile: args="check {case} --set track.seg-ments=1"
-- hostile: expect="<command line>: --set track.seg-ments=1: 'seg-ments' is neither"
-- Characters that cannot be in a key.
track { segments = { tangent { length = 100 } } }
