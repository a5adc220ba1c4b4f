-- Must-fail deck: a Lua syntax error is a deck error at the line Lua reports.
-- EXPECT_ERROR: lua_syntax_error\.lua:6: unexpected symbol near '='
-- EXPECT_STATUS: 2
DEBUT()

MAT = = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
FIN()
