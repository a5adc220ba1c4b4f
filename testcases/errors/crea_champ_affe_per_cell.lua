-- Must-fail deck: CREA_CHAMP AFFE builds fields at nodes; a TYPE_CHAM per cell (ELGA_) is refused.
-- EXPECT_ERROR: crea_champ_affe_per_cell\.lua:6: CREA_CHAMP: TYPE_CHAM: expected a field at nodes, NOEU_<quantity>_R or _F, with OPERATION='AFFE', got 'ELGA_NEUT_R'
-- EXPECT_ERROR: fields per cell \(ELGA_, ELNO_, ELEM_, CART_\) come from results \(EXTR\)
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
F = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'ELGA_NEUT_R', MODELE = MO,
                AFFE = _F{ TOUT = 'OUI', NOM_CMP = 'X1', VALE = 1.0 } }
FIN()
