-- Must-fail deck: SSNP121 A (CONTINUE contact, multipliers) solved with SOLVEUR METHODE='PETSC',
-- CG + GAMG. Once contact is active the system is a saddle point, which neither CG nor
-- multigrid can take: the run stops with a solve failure that names the choice that works,
-- instead of iterating to NMAX_ITER or calling the system singular.
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: petsc_saddle_point_multigrid\.lua:21: STAT_NON_LINE: the iterative solver PETSc CG \+ GAMG cannot solve this system: it has contact multipliers
-- EXPECT_ERROR: needs PRE_COND='LDLT_SP' with ALGORITHME='FGMRES' or 'GMRES'
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
-- The system of the first pass (no contact point active yet) is SPD and solves; the
-- second one has active multipliers.
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST },
                      SOLVEUR = _F{ METHODE = 'PETSC', ALGORITHME = 'CG', PRE_COND = 'GAMG' } }
FIN()
