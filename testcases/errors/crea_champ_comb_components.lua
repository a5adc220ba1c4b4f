-- Must-fail deck: CREA_CHAMP COMB adds fields of the same components; DX alone and DX, DY differ.
-- EXPECT_ERROR: crea_champ_comb_components\.lua:8: CREA_CHAMP: COMB\[2\]\.CHAM_GD: expected a field of NOEU_DEPL_R with the components of 'U', got 'A', of NOEU_DEPL_R
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
U = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_DEPL_R', NOM_CHAM = 'DEPL', RESULTAT = R, NUME_ORDRE = 1 }
A = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_DEPL_R', MAILLAGE = MA,
                AFFE = _F{ TOUT = 'OUI', NOM_CMP = 'DX', VALE = 1.0 } }
S = CREA_CHAMP{ OPERATION = 'COMB', TYPE_CHAM = 'NOEU_DEPL_R',
                COMB = { _F{ CHAM_GD = U, COEF_R = 1.0 }, _F{ CHAM_GD = A, COEF_R = 1.0 } } }
FIN()
