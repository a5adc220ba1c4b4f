-- Must-fail deck: DEFI_LIST_REEL steps: PAS > 0 and NOMBRE >= 1 (catalogue bounds, both
-- reported at once).
-- EXPECT_ERROR: list_step_not_positive\.lua:7: DEFI_LIST_REEL: INTERVALLE\[1\]\.PAS: expected real > 0, got 0
-- EXPECT_ERROR: also INTERVALLE\[2\]\.NOMBRE: expected integer >= 1, got 0
-- EXPECT_STATUS: 2
DEBUT()
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = { _F{ JUSQU_A = 1.0, PAS = 0.0 }, _F{ JUSQU_A = 2.0, NOMBRE = 0 } } }
FIN()
