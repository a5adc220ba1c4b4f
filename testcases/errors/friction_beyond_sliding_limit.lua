-- Must-fail deck: testcases/friction_sliding_limit.lua pushing with 101 % of mu p: Coulomb friction cannot
-- hold the block, which slides with nothing to stop it; the run names the body free along x and says
-- that every closed contact point slips.
-- EXPECT_ERROR: friction_beyond_sliding_limit\.lua:21: STAT_NON_LINE: the stiffness matrix is singular at instant 2\.000000e\+00: the body PLAQUE1 \(64 cells\) has a rigid-body mode \(free to move along DX
-- EXPECT_ERROR: all 16 closed contact points slip at the last iterate: Coulomb friction holds at most mu times the normal force
-- EXPECT_STATUS: 3
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
local mu, p, L = 0.3, 1.0e6, 2.0
FIX = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'GH', DX = 0.0, DY = 0.0 } }
PRESS = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'CD', PRES = p } }
PUSH = AFFE_CHAR_MECA{ MODELE = MO, FORCE_CONTOUR = _F{ GROUP_MA = 'CD', FX = 1.01 * mu * p } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', FROTTEMENT = 'COULOMB',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COULOMB = mu } }
L_INST = DEFI_LIST_REEL{ VALE = { 0.0, 1.0, 2.0 } }
R1 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0, 2.0, 1.0 } }
R2 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 2.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = { _F{ CHARGE = FIX }, _F{ CHARGE = PRESS, FONC_MULT = R1 }, _F{ CHARGE = PUSH, FONC_MULT = R2 } },
                      INCREMENT = _F{ LIST_INST = L_INST }, CONVERGENCE = _F{ RESI_GLOB_RELA = 1e-9 } }
FIN()
