-- Must-fail deck: a budget line below the first line of code would be read too late to matter; it is refused.
-- EXPECT_ERROR: budget_header_below_code\.lua:5: budget header: expected the '-- lunaster:' budget line in the comment block at the top of the deck, got it below the first line of code
-- EXPECT_STATUS: 2
DEBUT()
-- lunaster: time_limit=60
FIN()
