-- Must-fail deck: E must be > 0 (open bound) and RHO >= 0 (closed bound); both
-- violations are reported at once.
-- EXPECT_ERROR: young_modulus_zero\.lua:7: DEFI_MATERIAU: ELAS\.E: expected real > 0, got 0
-- EXPECT_ERROR: also ELAS\.RHO: expected real >= 0, got -1
-- EXPECT_STATUS: 2
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 0.0, NU = 0.3, RHO = -1.0 } }
FIN()
