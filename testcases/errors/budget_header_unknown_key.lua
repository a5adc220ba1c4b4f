-- Must-fail deck: a misspelt budget key in the header is refused with the closest key.
-- EXPECT_ERROR: budget_header_unknown_key\.lua:5: budget header: expected time_limit=SECONDS or memory_limit=MB, got 'timelimit=60'
-- EXPECT_ERROR: did you mean 'time_limit'\?
-- EXPECT_STATUS: 2
-- lunaster: timelimit=60
DEBUT()
FIN()
