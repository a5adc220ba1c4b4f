-- Must-fail deck: DEFI_LIST_REEL VALE must increase strictly.
-- EXPECT_ERROR: list_values_not_increasing\.lua:5: DEFI_LIST_REEL: VALE: expected strictly increasing values, got 0\.5 after 1 \(value 3\)
-- EXPECT_STATUS: 2
DEBUT()
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0, 0.5 } }
FIN()
