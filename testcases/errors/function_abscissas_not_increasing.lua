-- Must-fail deck: the abscissas of DEFI_FONCTION VALE must increase strictly; the
-- command names the pair that does not (x3 repeats x2).
-- EXPECT_ERROR: function_abscissas_not_increasing\.lua:6: DEFI_FONCTION: VALE: expected strictly increasing abscissas x1 < x2 < \.\.\., got x3 = 1 after x2 = 1 \(value 5 of VALE\)
-- EXPECT_STATUS: 2
DEBUT()
F = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0, 1.0, 2.0 } }
FIN()
