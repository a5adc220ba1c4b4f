-- Must-fail deck: a text given where a real is expected.
-- EXPECT_ERROR: wrong_type\.lua:5: DEFI_MATERIAU: ELAS\.E: expected real > 0, got 'steel'
-- EXPECT_STATUS: 2
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 'steel', NU = 0.3 } }
FIN()
