-- Must-fail deck: Poisson's ratio outside (-1, 0.5).
-- EXPECT_ERROR: value_out_of_range\.lua:5: DEFI_MATERIAU: ELAS\.NU: expected real in \(-1, 0\.5\), got 0\.7
-- EXPECT_STATUS: 2
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.7 } }
FIN()
