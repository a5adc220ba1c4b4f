-- Must-fail deck: a deck reads a table row that does not exist.
-- EXPECT_ERROR: table_cell_out_of_range\.lua:6: table T\['DY'\]: row 2 out of range \(the table has 1 row\(s\): 1\.\.1\)
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'TOP', RESULTANTE = 'DY', NUME_ORDRE = 1 } }
local f = T['DY'][2]
FIN()
