-- Must-fail deck: SOLVEUR FILTRAGE_MATRICE = 0.5. An entry is left out when |a_ij| <= FILTRAGE_MATRICE
-- (|a_ii| + |a_jj|): from 0.5 on, every diagonal entry would go and no matrix would be left to
-- factorise. The catalogue refuses it, naming the keyword, the range and the value given.
-- EXPECT_ERROR: mumps_filtrage_matrice_half\.lua:14: STAT_NON_LINE: SOLVEUR\.FILTRAGE_MATRICE: expected real < 0\.5, got 0\.5
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
                      SOLVEUR = _F{ METHODE = 'MUMPS', FILTRAGE_MATRICE = 0.5 } }
FIN()
