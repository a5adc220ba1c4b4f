-- Must-fail deck: DEFORMATION = 'GROT_GDEP' (large rotations) on a C_PLAN model: the thickness
-- stretch of plane stress is unknown to the large-rotation kinematics, refused in keyword terms.
-- EXPECT_ERROR: deformation_grot_gdep_c_plan\.lua:14: STAT_NON_LINE: COMPORTEMENT\[1\]\.DEFORMATION: expected 'PETIT' on the cells of a C_PLAN model, got 'GROT_GDEP' on the C_PLAN cell
-- EXPECT_ERROR: model the part in D_PLAN or 3D
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/unit_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN' } }
STEEL = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e5, NU = 0.3 }, ECRO_LINE = _F{ D_SIGM_EPSI = 2000.0, SY = 200.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = STEEL } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = 0.01 } } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L },
                   COMPORTEMENT = _F{ RELATION = 'VMIS_ISOT_LINE', DEFORMATION = 'GROT_GDEP', TOUT = 'OUI' } }
FIN()
