-- Must-fail deck: CREA_CHAMP builds fields at nodes. A per-cell type of code_aster's
-- analytical-solution decks (ELGA_NEUT_R) is refused by name with the reason
-- (crea_champ_affe_result_type.lua: a per-cell type that results give).
-- EXPECT_ERROR: crea_champ_affe_per_cell\.lua:7: CREA_CHAMP: TYPE_CHAM: expected one of .* \(a field per cell or integration point built from constants, functions or other fields: lunaster builds such fields at nodes \(NOEU_\*\)\), got 'ELGA_NEUT_R'
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
F = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'ELGA_NEUT_R', MODELE = MO,
                AFFE = _F{ TOUT = 'OUI', NOM_CMP = 'X1', VALE = 1.0 } }
FIN()
