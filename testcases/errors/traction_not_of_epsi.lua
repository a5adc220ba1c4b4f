-- Must-fail deck: TRACTION's SIGM is a function of the strain EPSI; a function of another
-- parameter (here of time) is refused, naming it.
-- EXPECT_ERROR: traction_not_of_epsi\.lua:7: DEFI_MATERIAU: TRACTION\.SIGM: expected a function of EPSI, got 'RAMP', a function of INST
-- EXPECT_STATUS: 2
DEBUT()
RAMP = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1000.0 } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e5, NU = 0.3 }, TRACTION = _F{ SIGM = RAMP } }
FIN()
