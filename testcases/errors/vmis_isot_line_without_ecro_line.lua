-- Must-fail deck: RELATION = 'VMIS_ISOT_LINE' needs the material's ECRO_LINE (its
-- D_SIGM_EPSI and SY); a material with ELAS alone is refused, naming it.
-- EXPECT_ERROR: vmis_isot_line_without_ecro_line\.lua:13: STAT_NON_LINE: COMPORTEMENT\[1\]\.RELATION: expected a material with ECRO_LINE on the cells of 'VMIS_ISOT_LINE', got 'VMIS_ISOT_LINE' on the material 'STEEL' without ECRO_LINE
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/unit_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
STEEL = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e5, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = STEEL } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = 0.01 } } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L },
                   COMPORTEMENT = _F{ RELATION = 'VMIS_ISOT_LINE', TOUT = 'OUI' } }
FIN()
