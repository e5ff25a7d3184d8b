-- hostile: args="check-result result.h5 --exit-code 0" forge=external_schema timeout=30
-- hostile: expect="/schema is an external link" unchanged=../victim.h5
-- Issue 47: check-result reads a result with an external link as any reader does: refused as a
-- whole (exit 1), nothing is read through the link.
return nil
