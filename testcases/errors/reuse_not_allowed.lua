-- Must-fail deck: reuse is only accepted by the commands that code_aster allows it for.
-- EXPECT_ERROR: reuse_not_allowed\.lua:7: DEFI_MATERIAU: reuse: expected no reuse \(DEFI_MATERIAU always creates a new concept\), got fonction RAMPE
-- EXPECT_STATUS: 2
DEBUT()

RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
MAT = DEFI_MATERIAU{ reuse = RAMPE, ELAS = _F{ E = 2.0e6, NU = 0.0 } }
FIN()
