-- Coulomb friction at its limit: a block pressed on another (p = 1e6 Pa on CD) and pushed along
-- the interface by a traction on CD of 99 % of mu p (mu = 0.3): the friction holds it. (Its twin
-- errors/friction_beyond_sliding_limit.lua pushes with 101 %: nothing holds the block, and the run
-- says so.) SSNP121's blocks, matching on y = 0 (testcases/friction_patch_2d.med), D_PLAN,
-- E = 2e11 Pa, NU = 0, GH fixed; CONTINUE, augmented Lagrangian friction; no shear on the sides,
-- so the interface's traction is not uniform and all its slave nodes but one slip.
-- Reference (analytical): equilibrium, the base carries the push: the reaction along x on GH is
-- -0.99 mu p L (L = 2 m), and along y p L; exact to the solve (1e-8).
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
local mu, p, L = 0.3, 1.0e6, 2.0
FIX = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'GH', DX = 0.0, DY = 0.0 } }
PRESS = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'CD', PRES = p } }
PUSH = AFFE_CHAR_MECA{ MODELE = MO, FORCE_CONTOUR = _F{ GROUP_MA = 'CD', FX = 0.99 * mu * p } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', FROTTEMENT = 'COULOMB',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COULOMB = mu } }
L_INST = DEFI_LIST_REEL{ VALE = { 0.0, 1.0, 2.0 } }
R1 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0, 2.0, 1.0 } }
R2 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 2.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = { _F{ CHARGE = FIX }, _F{ CHARGE = PRESS, FONC_MULT = R1 }, _F{ CHARGE = PUSH, FONC_MULT = R2 } },
                      INCREMENT = _F{ LIST_INST = L_INST }, CONVERGENCE = _F{ RESI_GLOB_RELA = 1e-9 } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, FORCE = 'REAC_NODA' }
T = POST_RELEVE_T{ ACTION = _F{ INTITULE = 'GH', RESULTAT = RESU, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'GH',
                                RESULTANTE = { 'DX', 'DY' }, OPERATION = 'EXTRACTION', NUME_ORDRE = 2 } }
TEST_TABLE{ TABLE = T, NOM_PARA = 'DX', VALE_CALC = -5.940000000e+05, REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.99 * mu * p * L,
            PRECISION = 1e-8 }
TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', VALE_CALC = 2.000000000e+06, REFERENCE = 'ANALYTIQUE', VALE_REFE = p * L, PRECISION = 1e-8 }
TEST_RESU{ RESU = {
  _F{ RESULTAT = RESU, NUME_ORDRE = 2, NOM_CHAM = 'CONT_NOEU', GROUP_NO = 'O', NOM_CMP = 'CONT', VALE_CALC = 2.0 },
  _F{ RESULTAT = RESU, NUME_ORDRE = 2, NOM_CHAM = 'CONT_NOEU', GROUP_NO = 'B', NOM_CMP = 'CONT', VALE_CALC = 1.0 },
} }
FIN()
