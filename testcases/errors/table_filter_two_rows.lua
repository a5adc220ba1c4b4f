-- Must-fail deck: TEST_TABLE without TYPE_TEST on a table where two rows remain.
-- EXPECT_ERROR: table_filter_two_rows\.lua:6: TEST_TABLE: FILTRE: expected filters leaving exactly one row of table T, got 2 row\(s\) left by INTITULE EQ 'TOP'
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'TOP', RESULTANTE = 'DY' } }
TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', FILTRE = _F{ NOM_PARA = 'INTITULE', VALE_K = 'TOP' }, VALE_CALC = 0.0 }
FIN()
