-- Must-fail deck: contact or linear relations with multipliers (LAGS_C: FORMULATION='CONTINUE' here;
-- LAGR_DX..: LIAISON_DDL without ELIM_LAGR) on a mesh read in parts (PARTITIONNEUR) make a
-- saddle-point system, which MUMPS solves on parts; PETSc's solvers and preconditioners of an SPD
-- system do not, and its node blocks would be cut by the multipliers (docs/distributed-model.md,
-- step 5). STAT_NON_LINE refuses it on every rank, naming what runs.
-- EXPECT_ERROR: parts_petsc_with_multipliers\.lua:19: STAT_NON_LINE: contact or linear relations with multipliers \(LAGS_C, LAGR_DX\.\.\) on a mesh in parts are solved by MUMPS, not PETSc
-- EXPECT_ERROR: SOLVEUR=_F\{ METHODE = 'MUMPS' \}, or no multipliers: contact by the discrete formulation's PENALISATION or by mortar \(DEFI_CONT\), linear relations with SOLVEUR ELIM_LAGR = 'OUI'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med', PARTITIONNEUR = 'PTSCOTCH' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CHA = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', ALGO_CONT = 'STANDARD' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                      SOLVEUR = _F{ METHODE = 'PETSC', ALGORITHME = 'GMRES', PRE_COND = 'JACOBI' } }
FIN()
