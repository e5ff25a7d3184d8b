-- hostile: args="assess track_only.h5" timeout=20
-- hostile: expect="nothing to assess in 'track_only.h5': it holds /stats, /track" expect="no /contact"
-- hostile: reject="no group asked"
-- track_only.h5 is the result of `workbench run scenarios/tracks/manchester_r500.lua` (a track with
-- no vehicle): assess must say what the file is and what it lacks, not only "no group asked".
return nil
