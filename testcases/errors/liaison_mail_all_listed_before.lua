-- Must-fail deck: two LIAISON_MAIL occurrences with the same slave nodes (AB). With ELIM_MULT = 'OUI'
-- (the default) the second leaves out the nodes the first listed, and has none left: the error says
-- so and names ELIM_MULT = 'NON' (which would tie them twice).
-- EXPECT_ERROR: liaison_mail_all_listed_before\.lua:9: AFFE_CHAR_MECA: LIAISON_MAIL\[2\]\.GROUP_MA_ESCL: expected slave nodes that no earlier LIAISON_MAIL of this AFFE_CHAR_MECA listed \(ELIM_MULT = 'OUI' leaves those out; 'NON' ties them again\), got all 17 listed before
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/liaison_mail_nested2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 },
                     LIAISON_MAIL = { _F{ GROUP_MA_MAIT = 'PLAQUE2', GROUP_MA_ESCL = 'AB' },
                                      _F{ GROUP_MA_MAIT = 'PLAQUE2', GROUP_MA_ESCL = 'AB' } } }
FIN()
