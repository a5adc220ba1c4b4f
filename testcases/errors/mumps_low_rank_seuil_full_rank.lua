-- Must-fail deck: SOLVEUR METHODE = 'MUMPS' with LOW_RANK_SEUIL but no low-rank ACCELERATION. The
-- threshold acts only on a block low-rank factorisation (ACCELERATION = 'LR'); beside the full-rank
-- default it would change nothing, so it is refused, naming the keyword, what fits and the remedy.
-- EXPECT_ERROR: mumps_low_rank_seuil_full_rank\.lua:15: STAT_NON_LINE: SOLVEUR\.LOW_RANK_SEUIL: expected 0 \(its default\) with ACCELERATION = 'AUTO' \(full rank\), got 1e-09
-- EXPECT_ERROR: give ACCELERATION = 'LR' beside it, or remove it
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/glued3d_hexa20.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                               _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST },
                      SOLVEUR = _F{ METHODE = 'MUMPS', LOW_RANK_SEUIL = 1.0e-9 } }
FIN()
