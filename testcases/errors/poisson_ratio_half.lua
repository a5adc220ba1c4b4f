-- Must-fail deck: NU = 0.5 (an incompressible material) is outside the open range
-- (-1, 0.5) where isotropic elasticity has a finite bulk modulus. It used to pass the
-- catalogue and stop later as an internal error (exit 4); it is a deck error (exit 2).
-- EXPECT_ERROR: poisson_ratio_half\.lua:7: DEFI_MATERIAU: ELAS\.NU: expected real in \(-1, 0\.5\), got 0\.5
-- EXPECT_STATUS: 2
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.5 } }
FIN()
