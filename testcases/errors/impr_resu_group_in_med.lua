-- Must-fail deck: GROUP_NO restricts the text table of FORMAT='RESULTAT'; a MED file holds the
-- whole mesh, so with FORMAT='MED' it is refused rather than ignored.
-- EXPECT_ERROR: impr_resu_group_in_med\.lua:14: IMPR_RESU: RESU\[1\]\.GROUP_NO: expected no GROUP_NO with FORMAT='MED' \(the MED file holds the whole mesh; FORMAT='RESULTAT' prints chosen nodes\), got GROUP_NO
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
IMPR_RESU{ FORMAT = 'MED', RESU = _F{ RESULTAT = R, GROUP_NO = 'TOP' } }
FIN()
