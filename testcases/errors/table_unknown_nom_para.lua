-- Must-fail deck: TEST_TABLE names a parameter the table lacks.
-- EXPECT_ERROR: table_unknown_nom_para\.lua:6: TEST_TABLE: NOM_PARA: expected a parameter of table T \(INTITULE, RESU, NOM_CHAM, NUME_ORDRE, INST, DY\), got 'DZ'
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'TOP', RESULTANTE = 'DY' } }
TEST_TABLE{ TABLE = T, NOM_PARA = 'DZ', VALE_CALC = 0.0 }
FIN()
