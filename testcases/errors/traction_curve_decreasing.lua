-- Must-fail deck: TRACTION's curve must not soften: a stress below the one before it is refused,
-- naming the point (the von Mises return with a piecewise hardening needs R(p) non-decreasing).
-- EXPECT_ERROR: traction_curve_decreasing\.lua:10: DEFI_MATERIAU: TRACTION\.SIGM: expected a traction curve \(its first point the yield point, E = SIGM/EPSI there\), got 'CURVE': the stresses must not decrease: point 3
-- EXPECT_STATUS: 2
DEBUT()
CURVE = DEFI_FONCTION{ NOM_PARA = 'EPSI', PROL_DROITE = 'CONSTANT',
                       VALE = { 0.005, 1000.0,
                                0.015, 1100.0,
                                0.035, 1050.0 } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e5, NU = 0.3 }, TRACTION = _F{ SIGM = CURVE } }
FIN()
