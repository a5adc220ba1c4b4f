-- Must-fail deck: code_aster's RENUM values belong to their METHODE (RCMK and SANS to LDLT; METIS,
-- MD and MDA to MULT_FRONT): RCMK with MULT_FRONT is refused before the solve starts.
-- EXPECT_ERROR: renum_of_another_methode\.lua:13: STAT_NON_LINE: SOLVEUR\.RENUM: expected one of 'METIS', 'MD', 'MDA', got 'RCMK'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/glued3d_hexa20.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                               _F{ GROUP_NO = 'SURCHA', DZ = -0.1 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L },
                   SOLVEUR = _F{ METHODE = 'MULT_FRONT', RENUM = 'RCMK' } }
FIN()
