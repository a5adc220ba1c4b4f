-- Must-fail deck: the FILTRE of TEST_TABLE leaves no row.
-- EXPECT_ERROR: table_filter_no_row\.lua:6: TEST_TABLE: FILTRE: expected filters leaving exactly one row of table T, got 0 row\(s\) left by NUME_ORDRE EQ 5
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'TOP', RESULTANTE = 'DY' } }
TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', FILTRE = _F{ NOM_PARA = 'NUME_ORDRE', VALE_I = 5 }, VALE_CALC = 0.0 }
FIN()
