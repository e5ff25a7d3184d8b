-- hostile: args="assess result.h5" forge=comfort_sample_every exit=0 timeout=30
-- hostile: expect="comfort: the run is shorter than one 5 s block of EN 12299; not assessed"
-- hostile: reject="internal error"
-- Found by the result fuzz harness: /assessment@sample_every (2.5 ms) disagrees with the time axis
-- (5 ms over 7 s). The comfort test passed on the times, the 5 s blocks counted in samples at the
-- stated interval were none, and an internal check ended assess with exit 3. Comfort is now not
-- assessed when a floor signal holds no whole block.
return nil
