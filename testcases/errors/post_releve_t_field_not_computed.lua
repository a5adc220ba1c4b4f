-- Must-fail deck: POST_RELEVE_T reads a field the result does not hold (FORC_NODA not asked of CALC_CHAMP).
-- EXPECT_ERROR: post_releve_t_field_not_computed\.lua:5: POST_RELEVE_T: ACTION\[1\]\.NOM_CHAM: expected a nodal field stored at NUME_ORDRE 0 \(DEPL, REAC_NODA\), got 'FORC_NODA'
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'FORC_NODA', GROUP_NO = 'TOP', RESULTANTE = 'DY' } }
FIN()
