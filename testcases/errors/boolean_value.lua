-- Must-fail deck: Lua booleans are not keyword values (code_aster uses 'OUI'/'NON').
-- EXPECT_ERROR: boolean_value\.lua:5: DEFI_FONCTION: PROL_GAUCHE: expected a real, an integer, a text or a concept, got a boolean
-- EXPECT_STATUS: 2
DEBUT()
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 }, PROL_GAUCHE = true }
FIN()
