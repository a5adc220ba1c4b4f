-- Must-fail deck: the values of a function are finite numbers (here 1/0 = inf).
-- EXPECT_ERROR: function_value_not_finite\.lua:5: DEFI_FONCTION: VALE: expected a finite real, got inf
-- EXPECT_STATUS: 2
DEBUT()
F = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1 / 0 } }
FIN()
