-- Must-fail deck: SSNP121 A (CONTINUE, CONTACT_INIT = 'NON') with SOLVEUR METHODE = 'MUMPS' and
-- PRETRAITEMENTS = 'SANS'. Without MUMPS's scaling its null-pivot test (NPREC = 8) compares the
-- pivots as assembled, and the contact multipliers' pivots (of order weight^2 / stiffness, far
-- below 1e-8 in these units) count as null once contact closes. The error says why and what to do
-- (PRETRAITEMENTS = 'AUTO', or NPREC = -1: testcases/solveur_options.lua runs that).
-- EXPECT_ERROR: mumps_pretraitements_sans\.lua:21: STAT_NON_LINE: the system at instant 1\.000000e\+00 is singular or too ill-conditioned for the linear solver: MUMPS: singular matrix at equation [0-9]+
-- EXPECT_ERROR: the matrix was factorised as assembled \(SOLVEUR PRETRAITEMENTS='SANS'\), so NPREC tested its pivots unscaled: a multiplier's pivot, small in absolute terms, counts as null; use PRETRAITEMENTS='AUTO' \(the default\), or NPREC=-1 to turn the test off
-- EXPECT_STATUS: 3
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
                                COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                      SOLVEUR = _F{ METHODE = 'MUMPS', PRETRAITEMENTS = 'SANS' } }
FIN()
