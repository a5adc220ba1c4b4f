-- Must-fail deck: LIAISON_MAIL with GROUP_MA_MAIT = 'SURMAI', a group of QUAD4 faces, in a 3D model:
-- the slave nodes follow master cells of the model's dimension (volumes), which that group has none of.
-- EXPECT_ERROR: liaison_mail_master_faces\.lua:8: AFFE_CHAR_MECA: LIAISON_MAIL\[1\]\.GROUP_MA_MAIT: expected volume cells \(HEXA, PENTA, TETRA\) of MODELE 'MO', got groups without any
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/liaison_mail_nested3d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'SURMAI', GROUP_MA_ESCL = 'SURESC' } }
FIN()
