-- Must-fail deck: a command called with a positional value instead of a keyword table.
-- EXPECT_ERROR: positional_argument\.lua:6: DEFI_MATERIAU: expected DEFI_MATERIAU\{ KEYWORD = value, \.\.\. \}, got 1 argument\(s\), the first being
-- EXPECT_STATUS: 2
DEBUT()

MAT = DEFI_MATERIAU('steel')
FIN()
