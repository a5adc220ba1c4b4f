-- Must-fail deck: each JUSQU_A of DEFI_LIST_REEL must lie beyond the previous point
-- (an empty or backward interval); the command names the interval.
-- EXPECT_ERROR: list_interval_not_increasing\.lua:6: DEFI_LIST_REEL: INTERVALLE\[2\]\.JUSQU_A: expected real > 1 \(the previous point of the list\), got 1
-- EXPECT_STATUS: 2
DEBUT()
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = { _F{ JUSQU_A = 1.0, NOMBRE = 2 }, _F{ JUSQU_A = 1.0, NOMBRE = 1 } } }
FIN()
