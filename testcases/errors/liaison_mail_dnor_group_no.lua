-- Must-fail deck: LIAISON_MAIL with DDL = 'DNOR' and the slave nodes given as GROUP_NO_ESCL: the
-- normal each slave node takes comes from the slave face's cells, which only GROUP_MA_ESCL gives.
-- EXPECT_ERROR: liaison_mail_dnor_group_no\.lua:8: AFFE_CHAR_MECA: LIAISON_MAIL\[1\]\.GROUP_NO_ESCL: expected with DDL = 'DNOR', the slave face as GROUP_MA_ESCL alone \(its cells give the normal\), got GROUP_NO_ESCL
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/liaison_mail_nested3d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'V2', GROUP_NO_ESCL = 'SURESC', DDL = 'DNOR' } }
FIN()
