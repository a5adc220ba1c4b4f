-- Must-fail deck: TEST_RESU RESU of an ELNO field (values at the cell's nodes) given an
-- integration point (POINT, for ELGA fields) instead of a node.
-- EXPECT_ERROR: test_resu_elno_point\.lua:7: TEST_RESU: RESU\[1\]\.MAILLE: expected NOEUD or GROUP_NO with an ELNO field \(the value at a node of the cell\), got 'M5' with POINT
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = 'SIGM_ELNO' }
TEST_RESU{ RESU = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_ELNO', NOM_CMP = 'SIYY', MAILLE = 'M5', POINT = 1,
                      VALE_CALC = 0.0 } }
FIN()
