-- Must-fail deck: a deck that solves and checks nothing (no TEST_RESU, no TEST_TABLE) proves nothing:
-- the run says NO_CHECK and ends with exit 1 (`lunaster verify` counts it failed, status NO_CHECK).
-- EXPECT_ERROR: ^lunaster: 0 check\(s\) OK, 0 NOOK$
-- EXPECT_ERROR: ^lunaster: NO_CHECK: the deck checked nothing \(it ran no TEST_RESU or TEST_TABLE\): exit status 1$
-- EXPECT_STATUS: 1
require('lib.reaction_scene')
FIN()
