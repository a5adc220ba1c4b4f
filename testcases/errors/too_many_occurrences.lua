-- Must-fail deck: a factor keyword given twice where code_aster allows one occurrence.
-- EXPECT_ERROR: too_many_occurrences\.lua:6: DEFI_MATERIAU: ELAS: expected at most 1 occurrence, got 2 occurrences
-- EXPECT_STATUS: 2
DEBUT()

MAT = DEFI_MATERIAU{ ELAS = { _F{ E = 2.0e6, NU = 0.3 }, _F{ E = 3.0e6, NU = 0.3 } } }
FIN()
