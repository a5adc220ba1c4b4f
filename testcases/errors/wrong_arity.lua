-- Must-fail deck: a list of two values where the keyword takes one (wrong arity).
-- EXPECT_ERROR: wrong_arity\.lua:6: DEFI_MATERIAU: ELAS\.NU: expected a single value \(real in \(-1, 0\.5\)\), got a list of 2 values
-- EXPECT_STATUS: 2
DEBUT()

MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = { 0.3, 0.2 } } }
FIN()
