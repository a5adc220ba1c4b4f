-- Must-fail deck: CREA_CHAMP OPERATION = 'DISC' (a field moved between nodes, cells and
-- integration points) is refused by name, with the reason.
-- EXPECT_ERROR: crea_champ_operation_disc\.lua:7: CREA_CHAMP: OPERATION: expected one of 'EXTR', 'AFFE', 'ASSE', 'COMB', 'EVAL' \(a field moved between nodes, cells and integration points: lunaster builds fields at nodes
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
U = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_DEPL_R', NOM_CHAM = 'DEPL', RESULTAT = R, NUME_ORDRE = 1 }
UG = CREA_CHAMP{ OPERATION = 'DISC', TYPE_CHAM = 'ELGA_DEPL_R' }
FIN()
