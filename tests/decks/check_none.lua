-- A deck that solves and checks nothing (no TEST_RESU, no TEST_TABLE) proves nothing: `run` ends it
-- normally (exit 0, as code_aster ends a study without TEST_RESU) with a NO_CHECK line, and
-- `lunaster verify` counts it as a failure, status NO_CHECK (CTest cli.run_no_check, cli.verify_no_check).
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../../testcases/meshes/unit_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = -0.01 } } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L } }
FIN()
