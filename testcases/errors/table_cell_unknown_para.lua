-- Must-fail deck: a deck reads a table parameter that does not exist.
-- EXPECT_ERROR: table_cell_unknown_para\.lua:6: table T: no parameter 'DZ'; its parameters: INTITULE, RESU, NOM_CHAM, NUME_ORDRE, INST, DY
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'TOP', RESULTANTE = 'DY', NUME_ORDRE = 1 } }
local f = T['DZ'][1]
FIN()
