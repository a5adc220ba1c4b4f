-- Must-fail deck: ECRO_LINE's D_SIGM_EPSI (the uniaxial curve's slope after yield) must be below
-- ELAS's E, as code_aster requires (the plastic modulus E D_SIGM_EPSI / (E - D_SIGM_EPSI) has no
-- meaning otherwise); the message says what to write for an elastic von Mises material instead.
-- EXPECT_ERROR: ecro_line_slope_not_below_e\.lua:9: DEFI_MATERIAU: ECRO_LINE\.D_SIGM_EPSI: expected a slope below ELAS E = 200000, got 200000
-- EXPECT_ERROR: keep D_SIGM_EPSI below E and give a large SY
-- EXPECT_STATUS: 2
DEBUT()
-- D_SIGM_EPSI = E
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e5, NU = 0.3 }, ECRO_LINE = _F{ D_SIGM_EPSI = 2.0e5, SY = 1000.0 } }
FIN()
