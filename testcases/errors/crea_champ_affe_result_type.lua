-- Must-fail deck: CREA_CHAMP AFFE builds fields at nodes; ELGA_SIEF_R, a type EXTR takes out of a
-- result, is refused by AFFE with the reason.
-- EXPECT_ERROR: crea_champ_affe_result_type\.lua:7: CREA_CHAMP: TYPE_CHAM: expected a field at nodes, NOEU_<quantity>_R or _F, with OPERATION='AFFE', got 'ELGA_SIEF_R'
-- EXPECT_ERROR: fields per cell \(ELGA_, ELNO_, ELEM_, CART_\) come from results \(EXTR\)
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
F = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'ELGA_SIEF_R', MODELE = MO,
                AFFE = _F{ TOUT = 'OUI', NOM_CMP = 'SIXX', VALE = 1.0 } }
FIN()
