-- Coulomb friction through automatic step subdivision (DEFI_LIST_INST / ECHEC / ACTION='DECOUPE'):
-- the slip case of testcases/friction_patch_2d.lua (its blocks and mesh, mu = 0.3, p = 1e6 Pa on
-- CD, the sides' shear mu p) with the drag DX = 1e-5 m on CD applied in one step from t = 1 to 2,
-- and ITER_GLOB_MAXI = 3: the step fails, and its pieces are split again where the interface
-- goes from stick to slip, 9 times in all (29 stored steps). Each failed attempt leaves the
-- contact points' friction states to be put back before its sub-steps; the end state is the
-- uniform one whatever the path, as friction_patch_2d.lua's in seven steps.
-- Reference (analytical): at t = 2 LAGS_C = -p, LAGS_F1 = -1 (slip), CONT = 2, SIXY = mu p.
-- Tolerances: 5e-5, friction_patch_2d.lua's (the pairing follows the 4e-6 m slide); LAGS_F1 exact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
local mu, p, d = 0.3, 1.0e6, 1.0e-5
FIX = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'GH', DX = 0.0, DY = 0.0 } }
PRESS = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'CD', PRES = p } }
PUSH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'CD', DX = d } }
SLIDE = AFFE_CHAR_MECA{ MODELE = MO, FORCE_CONTOUR = { _F{ GROUP_MA = { 'BC', 'FG' }, FY = mu * p },
                                                      _F{ GROUP_MA = { 'DA', 'HE' }, FY = -mu * p } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', FROTTEMENT = 'COULOMB',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COULOMB = mu } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0, 2.0 } }
LI = DEFI_LIST_INST{ DEFI_LIST = _F{ LIST_INST = L },
                     ECHEC = _F{ EVENEMENT = 'ERREUR', ACTION = 'DECOUPE', SUBD_PAS = 4, SUBD_NIVEAU = 5 } }
R1 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0, 2.0, 1.0 } }
R2 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 2.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = { _F{ CHARGE = FIX }, _F{ CHARGE = PRESS, FONC_MULT = R1 },
                                _F{ CHARGE = PUSH, FONC_MULT = R2 }, _F{ CHARGE = SLIDE, FONC_MULT = R2 } },
                      INCREMENT = _F{ LIST_INST = LI }, CONVERGENCE = _F{ RESI_GLOB_RELA = 1e-9, ITER_GLOB_MAXI = 3 } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = 'SIGM_NOEU' }
local function check(field, node, cmp, refe, calc, tol)
  return _F{ RESULTAT = RESU, INST = 2.0, NOM_CHAM = field, GROUP_NO = node, NOM_CMP = cmp, VALE_CALC = calc,
             REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = tol }
end
TEST_RESU{ RESU = {
  check('DEPL', 'O', 'LAGS_C', -p, -1.000000194e+06, 5e-5),
  check('DEPL', 'A', 'LAGS_F1', -1.0, -1.0, 1e-8),
  check('DEPL', 'B', 'LAGS_F1', -1.0, -1.0, 1e-8),
  check('CONT_NOEU', 'O', 'CONT', 2.0, 2.0, 1e-12),
  check('SIGM_NOEU', 'C', 'SIXY', mu * p, 2.999994767e+05, 5e-5),
  check('SIGM_NOEU', 'H', 'SIXY', mu * p, 3.000001623e+05, 5e-5),
  -- the last of the 29 stored steps is t = 2
  _F{ RESULTAT = RESU, NUME_ORDRE = 29, PARA = 'INST', VALE_CALC = 2.0, REFERENCE = 'ANALYTIQUE', VALE_REFE = 2.0, PRECISION = 1e-12 },
} }
FIN()
