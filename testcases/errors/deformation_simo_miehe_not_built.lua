-- Must-fail deck: DEFORMATION = 'SIMO_MIEHE' is code_aster's but not built in lunaster:
-- refused with the reason, also under RELATION = 'ELAS'.
-- EXPECT_ERROR: deformation_simo_miehe_not_built\.lua:13: STAT_NON_LINE: COMPORTEMENT\[1\]\.DEFORMATION: expected 'PETIT' \(small strains\) or 'GROT_GDEP' \(large rotations\), got 'SIMO_MIEHE'
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
                   COMPORTEMENT = _F{ RELATION = 'ELAS', DEFORMATION = 'SIMO_MIEHE', TOUT = 'OUI' } }
FIN()
