-- Must-fail deck: DEBUT (with INTERVALLE) and VALE are mutually exclusive in DEFI_LIST_REEL.
-- EXPECT_ERROR: mutually_exclusive\.lua:5: DEFI_LIST_REEL: expected exactly one of DEBUT, VALE, got DEBUT and VALE
-- EXPECT_STATUS: 2
DEBUT()
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 2 }, VALE = { 0.0, 1.0 } }
FIN()
