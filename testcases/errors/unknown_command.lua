-- Must-fail deck: a misspelt command name is an unknown global, reported with
-- the closest command name before anything runs.
-- EXPECT_ERROR: unknown_command\.lua:8: unknown name 'DEFI_MATERIAUX' \(did you mean DEFI_MATERIAU\?\)
-- EXPECT_STATUS: 2
DEBUT()

-- the next line is the error
MAT = DEFI_MATERIAUX{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
FIN()
