-- Must-fail deck: SOLVEUR FILTRAGE_MATRICE on a contact system. MUMPS factorises the matrix
-- without its entries |a_ij| <= FILTRAGE_MATRICE (|a_ii| + |a_jj|), as code_aster's MUMPS driver
-- filters them. SSNP121 A's contact couplings are integration weights (lengths, in m) beside a
-- diagonal of the order of E = 2e6 Pa, and at 1e-9 the filter leaves out some that hold the
-- multipliers: the first pass (no point in contact) solves, the next one cannot reach
-- RESI_RELA. The run stops naming the approximation first, then FILTRAGE_MATRICE as the cause
-- and the remedy.
-- EXPECT_ERROR: mumps_filtrage_matrice_contact\.lua:23: STAT_NON_LINE: the system at instant 1\.0+e\+00, factorised approximately as asked \(without its smallest entries\), could not be solved to the accuracy asked
-- EXPECT_ERROR: SOLVEUR FILTRAGE_MATRICE left out entries this system needs \(its contact couplings are small beside the stiffness's diagonal\): lower it, or remove it \(the default, -1, keeps every entry\)
-- EXPECT_STATUS: 3
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                               _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON',
                                ORDRE_INT = 4, COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, CONTACT = CONT, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                      SOLVEUR = _F{ METHODE = 'MUMPS', FILTRAGE_MATRICE = 1.0e-9 } }
FIN()
