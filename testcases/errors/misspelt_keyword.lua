-- Must-fail deck: a misspelt keyword is rejected with the closest valid keyword.
-- EXPECT_ERROR: misspelt_keyword\.lua:6: DEFI_MATERIAU: ELAS\.NUU: expected a keyword of ELAS, got unknown keyword 'NUU'
-- EXPECT_ERROR: did you mean 'NU'\?
-- EXPECT_STATUS: 2
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NUU = 0.0 } }
FIN()
