-- Must-fail deck: TEST_TABLE VALE_CALC_I tests an integer column; DY, a real column, is refused
-- (VALE_CALC tests it).
-- EXPECT_ERROR: test_table_vale_calc_i_real\.lua:8: TEST_TABLE: VALE_CALC_I: expected VALE_CALC \(the value tested is a real\), got an integer reference
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'REAC_NODA',
                                GROUP_NO = 'TOP', RESULTANTE = 'DY', NUME_ORDRE = 1 } }
TEST_TABLE{ TABLE = T, NOM_PARA = 'DY',
            VALE_CALC_I = 1 }
FIN()
