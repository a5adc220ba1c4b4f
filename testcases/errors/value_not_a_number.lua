-- Must-fail deck: 0/0 is NaN, which no real keyword accepts (NaN also passes every bound
-- check, since each comparison with it is false: it has to be refused as such).
-- EXPECT_ERROR: value_not_a_number\.lua:6: DEFI_MATERIAU: ELAS\.E: expected a finite real > 0, got nan
-- EXPECT_STATUS: 2
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 0 / 0, NU = 0.3 } }
FIN()
