-- Must-fail deck: SOLVEUR MATR_DISTRIBUEE = 'NON' asks every rank to assemble the whole system,
-- which no rank holds on a mesh read in parts: refused, rather than ignored.
-- EXPECT_ERROR: parts_matr_distribuee_non\.lua:14: STAT_NON_LINE: SOLVEUR\.MATR_DISTRIBUEE: expected 'OUI' on a mesh in parts \(each rank holds its part, the matrix is given in parts\), got 'NON'
-- EXPECT_ERROR: remove MATR_DISTRIBUEE, or read the mesh without PARTITIONNEUR
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/block_hexa8_12.med', PARTITIONNEUR = 'PTSCOTCH' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e8 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                   INCREMENT = _F{ LIST_INST = L }, SOLVEUR = _F{ METHODE = 'MUMPS', MATR_DISTRIBUEE = 'NON' } }
FIN()
