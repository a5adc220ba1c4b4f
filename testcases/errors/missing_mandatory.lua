-- Must-fail deck: a mandatory keyword is missing.
-- EXPECT_ERROR: missing_mandatory\.lua:5: DEFI_MATERIAU: ELAS\.E: expected real > 0 \(mandatory keyword\), got nothing
-- EXPECT_STATUS: 2
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ NU = 0.3 } }
FIN()
