-- Must fail under mpirun only (tests/mpi/mpi_runs.py, errors): SOLVEUR RENUM='METIS' orders
-- the whole matrix in one process, and under mpirun each rank holds only its rows. The run
-- stops at STAT_NON_LINE naming the keyword, what is accepted and what was given. Serially the
-- same deck runs (MUMPS ordered by METIS).
-- EXPECT_STATUS: 2
-- EXPECT_ERROR: renum_metis\.lua:17: STAT_NON_LINE: SOLVEUR\.RENUM: expected
-- EXPECT_ERROR: 'AUTO', 'AMD', 'AMF', 'QAMD' or 'PORD' under mpirun .*got 'METIS'
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../../testcases/meshes/patch_quad4.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'TOP' } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
LOAD = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                       PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e4 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = LOAD }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                   SOLVEUR = _F{ METHODE = 'MUMPS', RENUM = 'METIS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
