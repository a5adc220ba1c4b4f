-- Must-fail deck: COMPORTEMENT GROUP_MA names cells of the model's mesh; an unknown group used to
-- be accepted unchecked (every cell is elastic, the only behaviour, but a typo is still a typo).
-- EXPECT_ERROR: behaviour_unknown_group\.lua:14: STAT_NON_LINE: COMPORTEMENT\[1\]\.GROUP_MA: expected a cell group of the mesh, got 'BLOK'
-- EXPECT_ERROR: did you mean 'BLOCK'\?
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/unit_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = -0.01 } } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L },
                   COMPORTEMENT = _F{ RELATION = 'ELAS', GROUP_MA = 'BLOK' } }
FIN()
