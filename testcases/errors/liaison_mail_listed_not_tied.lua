-- Must-fail deck: the clamped nodes ENCAST are slave nodes of a first LIAISON_MAIL, which leaves them
-- free (DISTANCE_MAX: they lie 1 m from V2), then the only slave nodes of a second. With ELIM_MULT =
-- 'OUI' an occurrence leaves out every slave node of the earlier ones, tied there or not, as
-- code_aster's does: the second has none left.
-- EXPECT_ERROR: liaison_mail_listed_not_tied\.lua:10: AFFE_CHAR_MECA: LIAISON_MAIL\[2\]\.GROUP_NO_ESCL: expected slave nodes that no earlier LIAISON_MAIL of this AFFE_CHAR_MECA listed \(ELIM_MULT = 'OUI' leaves those out; 'NON' ties them again\), got all 81 listed before
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/liaison_mail_nested3d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     LIAISON_MAIL = {
                       _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURESC', GROUP_NO_ESCL = 'ENCAST',
                           DISTANCE_MAX = 0.5 },
                       _F{ GROUP_MA_MAIT = 'V2', GROUP_NO_ESCL = 'ENCAST' } } }
FIN()
