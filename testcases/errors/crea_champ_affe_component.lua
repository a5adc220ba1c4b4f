-- Must-fail deck: CREA_CHAMP AFFE of a NOEU_DEPL_R field given a component DEPL does not have.
-- EXPECT_ERROR: crea_champ_affe_component\.lua:5: CREA_CHAMP: AFFE\[2\]\.NOM_CMP: expected a component of DEPL \(DX, DY, DZ, DRX, DRY, DRZ, LAGS_C, LAGS_F1, LAGS_F2\), got 'TEMP'
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
F = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_DEPL_R', MAILLAGE = MA,
                AFFE = { _F{ TOUT = 'OUI', NOM_CMP = 'DX', VALE = 1.0 },
                         _F{ GROUP_NO = 'TOP', NOM_CMP = 'TEMP', VALE = 1.0 } } }
FIN()
