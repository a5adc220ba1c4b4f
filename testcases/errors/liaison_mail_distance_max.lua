-- Must-fail deck: LIAISON_MAIL whose DISTANCE_MAX (1e-4 m) is below the gap (1e-3 m) between the
-- slave nodes and the master cell: no slave node is left to tie. The error counts why.
-- EXPECT_ERROR: liaison_mail_distance_max\.lua:8: AFFE_CHAR_MECA: LIAISON_MAIL\[1\]\.DISTANCE_MAX: expected slave nodes within DISTANCE_MAX of a master cell, got 2 slave node\(s\) beyond it \(the nearest 0\.001 m from a master cell\)
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'GMSH', FICHIER = '../meshes/liaison_mail_gap_v22.msh' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                     LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'LOWER', GROUP_MA_ESCL = 'UPPER_BOTTOM',
                                        DISTANCE_MAX = 1.0e-4 } }
FIN()
