-- Must-fail deck: the FILTRE of TEST_TABLE leaves no row.
-- EXPECT_ERROR: table_filter_no_row\.lua:15: TEST_TABLE: FILTRE: expected filters leaving exactly one row of table T, got 0 row\(s\) left by NUME_ORDRE EQ 5
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/unit_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = -0.01 } } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L } }
R = CALC_CHAMP{ reuse = R, RESULTAT = R, FORCE = 'REAC_NODA' }
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'TOP', RESULTANTE = 'DY' } }
TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', FILTRE = _F{ NOM_PARA = 'NUME_ORDRE', VALE_I = 5 }, VALE_CALC = 0.0 }
FIN()
