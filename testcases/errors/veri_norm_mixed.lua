-- Must-fail deck: one pressure group whose cells point both ways. The distorted QUAD8 block is meshed
-- clockwise (meshes/patch_quad8_cw.med): its edges point inward. TOP is oriented (ORIE_PEAU_2D), RIGHT
-- is not, and the group LOADED gathers both: 3 of its 6 SEG3 cells point into the body, 3 out of it.
-- Refused (AFFE_CHAR_MECA VERI_NORM = 'OUI', the default), saying how many each way, in C_PLAN.
-- EXPECT_ERROR: veri_norm_mixed\.lua:15: AFFE_CHAR_MECA: PRES_REP\[1\]\.GROUP_MA: expected boundary cells whose normal points out of the body they bound \(VERI_NORM = 'OUI'\), got group 'LOADED': 3 of 6 cells point into their body \(M5, M7, M11\), 3 out of it: mixed orientation$
-- EXPECT_ERROR: ORIE_PEAU_2D = _F\{ GROUP_MA = 'LOADED' \}
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad8_cw.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'TOP' } }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA, CREA_GROUP_MA = _F{ NOM = 'LOADED', GROUP_MA = { 'TOP', 'RIGHT' } } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'LOADED', PRES = 1.0e4 } }
FIN()
