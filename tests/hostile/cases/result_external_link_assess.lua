-- hostile: args="assess result.h5" forge=external_schema unchanged=../victim.h5 timeout=30
-- hostile: expect="/schema is an external link to '../victim.h5:/schema'" expect="result.h5"
-- hostile: reject="replaced /assessment"
-- Issue 47: /schema of a result is an HDF5 external link to a file outside the work folder.
-- assess opened the file's copy for writing, so HDF5 opened the linked file for writing too, and
-- replacing /schema/assessment rewrote that other file (exit 0). A result is read only from
-- itself: the file is refused before anything is written, and victim.h5 is left as it was.
return nil
