-- Must-fail deck: SSNP121 C's scene (DISCRETE PENALISATION, slave EF, master AB) with
-- E_N = 1e14, 5e7 times E: a pivot of the system loses 8.1 significant digits, more than
-- code_aster's default NPREC = 8. The elastic part is regular, so the run must stop blaming the
-- contact terms, name the digits, and offer NPREC (testcases/solver_singularity.lua runs it with
-- NPREC = 10).
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: penalty_too_stiff_nprec\.lua:20: STAT_NON_LINE: the system at instant 1\.0+e\+00 is singular or too ill-conditioned for the linear solver: CHOLMOD: numerically singular matrix \(pivot lost 8\.[0-9] significant digits \(more than 8\)\)
-- EXPECT_ERROR: E_N \(PENALISATION\) or COEF_CONT \(CONTINUE\) is not many orders of magnitude above the material stiffness
-- EXPECT_ERROR: or raise SOLVEUR NPREC above 8 \(the digits a pivot may lose\): the solve's accuracy is still checked
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 }, _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', REAC_GEOM = 'AUTOMATIQUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB', ALGO_CONT = 'PENALISATION', E_N = 1.0e14 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, CONTACT = CONT, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
