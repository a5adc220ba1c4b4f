-- Must-fail deck: reading a global that was never assigned is an error at read
-- time (strict globals), with the closest known name.
-- EXPECT_ERROR: undefined_global\.lua:8: unknown name 'YOUNGS' \(did you mean YOUNG\?\)
-- EXPECT_STATUS: 2
DEBUT()

YOUNG = 2.0e6
MAT = DEFI_MATERIAU{ ELAS = _F{ E = YOUNGS, NU = 0.0 } }
FIN()
