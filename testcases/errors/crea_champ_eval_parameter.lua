-- Must-fail deck: CREA_CHAMP EVAL of a function of Y with only a temperature field as CHAM_PARA:
-- no field gives the parameter Y.
-- EXPECT_ERROR: crea_champ_eval_parameter\.lua:11: CREA_CHAMP: CHAM_PARA: expected fields giving the parameter Y of 'F_Y' \(X1\) at node N1, got none that has it there
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
F_Y = FORMULE{ VALE = '2 * Y', NOM_PARA = 'Y' }
FF = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_NEUT_F', MAILLAGE = MA,
                 AFFE = _F{ TOUT = 'OUI', NOM_CMP = 'X1', VALE_F = F_Y } }
T = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_TEMP_R', MAILLAGE = MA,
                AFFE = _F{ TOUT = 'OUI', NOM_CMP = 'TEMP', VALE = 20.0 } }
V = CREA_CHAMP{ OPERATION = 'EVAL', TYPE_CHAM = 'NOEU_NEUT_R', CHAM_F = FF, CHAM_PARA = T }
FIN()
