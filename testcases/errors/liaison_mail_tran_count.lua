-- Must-fail deck: LIAISON_MAIL's TRAN with three values in a plane-strain model: TRAN moves each
-- slave node in the model's coordinates, two in 2D.
-- EXPECT_ERROR: liaison_mail_tran_count\.lua:8: AFFE_CHAR_MECA: LIAISON_MAIL\[1\]\.TRAN: expected 2 values \(one per coordinate of the 2D model\), got 3
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                     LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'BLOCK', GROUP_MA_ESCL = 'LEFT', TRAN = { 1.0, 0.0, 0.0 } } }
FIN()
