-- Must-fail deck: LIAISON_MAIL whose slave face SURMAI belongs to the master block V2 itself: each
-- slave node is a node of the master cell that holds it (it would follow itself). The error says so
-- and what GROUP_MA_MAIT should name.
-- EXPECT_ERROR: liaison_mail_slave_in_master\.lua:10: AFFE_CHAR_MECA: LIAISON_MAIL\[1\]\.GROUP_MA_ESCL: expected slave nodes that are not nodes of the master cell holding them, got 25 slave node\(s\), each a node of its master cell \(tied to itself\)
-- EXPECT_ERROR: GROUP_MA_MAIT names the cells the slave nodes follow: those of the other body
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/liaison_mail_nested3d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURMAI' } }
FIN()
