-- Must-fail deck: a budget in the header that is not a positive number is refused before the deck runs.
-- EXPECT_ERROR: budget_header_bad_value\.lua:4: budget header: memory_limit: expected a positive number of MB, got '512MB'
-- EXPECT_STATUS: 2
-- lunaster: time_limit=60 memory_limit=512MB
DEBUT()
FIN()
