-- Must-fail deck: a value outside the allowed list, with the closest allowed value.
-- EXPECT_ERROR: value_outside_into\.lua:6: DEFI_FONCTION: PROL_DROITE: expected one of 'EXCLU', 'CONSTANT', 'LINEAIRE', got 'CONSTNAT'
-- EXPECT_ERROR: did you mean 'CONSTANT'\?
-- EXPECT_STATUS: 2
DEBUT()
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 }, PROL_DROITE = 'CONSTNAT' }
FIN()
