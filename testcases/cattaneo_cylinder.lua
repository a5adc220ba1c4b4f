-- Cattaneo's problem: an elastic cylinder pressed on an elastic block, then pushed sideways
-- below the sliding load. Coulomb friction (mu = 0.2), CONTINUE (augmented Lagrangian), D_PLAN.
-- Mesh: lunaster-meshgen --hertz quad4:400 --grading 1.1 --full -o cattaneo_cylinder.med: the
-- cylinder (R = 1 m, BALL, its flat top BALL_TOP at y = R) on the block BLOCK = [-1,1]x[-1,0],
-- touching at O; QUAD4 of h0 = 2.5e-3 m in a uniform core of +-0.025 m around O (3947 nodes).
-- Identical materials (E = 1e9 Pa, nu = 0.3): the normal and tangential problems decouple
-- (Dundurs' beta = 0), as Cattaneo's solution assumes.
-- Loads: (t in [0, 1]) a pressure P/(2R) on BALL_TOP, P per unit length giving the Hertz half-width
-- a = 0.04 m (a = sqrt(4 P R / (pi E*)), 1/E* = 2 (1 - nu^2)/E); BALL_TOP is kept straight
-- (LIAISON_UNIF DY): a tangential force on a cylinder would roll it, and Cattaneo's bodies do not
-- turn. (t in [1, 2]) BALL_TOP moved by DX = 7e-4 m in two increments (monotonic, as Cattaneo's
-- Q): the reaction along x there is the tangential force Q, 0.714 mu P.
-- Reference (Johnson, Contact Mechanics, ch. 7): the stick zone |x| < c with c/a = (1 - Q/(mu P))^(1/2),
-- Q read from the run's reaction (REFERENCE = 'ANALYTIQUE': Cattaneo's law at the run's own Q); at the
-- centre the tangential traction over mu p0 is 1 - c/a (code_aster's semi-multiplier LAGS_F1 there,
-- negative: the block's tangent points along -x), and the pressure p0 = 2 P/(pi a).
-- Tolerances: p0 1e-2 (6.2e-3 here; Hertz idealises the cylinder and the block as half-spaces: the
-- block is 25 a wide, and a/R = 0.04); LAGS_F1 at O 1e-2 (2.8e-3 here). The stick zone's edge lies
-- between nodes: the slave nodes at |x| = 0.0175 m stick (CONT = 1) and those at |x| = 0.025 m slip
-- (CONT = 2), i.e. c = 0.0214 m located to within h0 on both sides.
DEBUT()
local R, E, NU, A, MU = 1.0, 1.0e9, 0.3, 0.04, 0.2
local E_STAR = 1.0 / (2.0 * (1.0 - NU ^ 2) / E)
local P = math.pi * E_STAR * A ^ 2 / (4.0 * R)
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
FIX = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BLOCK_BOTTOM', DX = 0.0, DY = 0.0 } }
STRAIGHT = AFFE_CHAR_MECA{ MODELE = MO, LIAISON_UNIF = _F{ GROUP_MA = 'BALL_TOP', DDL = 'DY' } }
PRESS = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'BALL_TOP', PRES = P / (2.0 * R) } }
SHIFT = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BALL_TOP', DX = 7.0e-4 } }
-- The cylinder is held by the contact alone: every slave point starts closed (CONTACT_INIT='OUI').
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', FROTTEMENT = 'COULOMB', ALGO_RESO_CONT = 'NEWTON',
                     ZONE = _F{ GROUP_MA_ESCL = 'BLOCK_TOP', GROUP_MA_MAIT = 'BALL_SURF', COULOMB = MU,
                                CONTACT_INIT = 'OUI' } }
L_INST = DEFI_LIST_REEL{ VALE = { 0.0, 1.0, 1.5, 2.0 } }
R1 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0, 2.0, 1.0 } }
R2 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 2.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = { _F{ CHARGE = FIX }, _F{ CHARGE = STRAIGHT }, _F{ CHARGE = PRESS, FONC_MULT = R1 },
                                _F{ CHARGE = SHIFT, FONC_MULT = R2 } },
                      INCREMENT = _F{ LIST_INST = L_INST }, CONVERGENCE = _F{ ITER_GLOB_MAXI = 40 } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, FORCE = 'REAC_NODA' }
TQ = POST_RELEVE_T{ ACTION = _F{ INTITULE = 'Q', RESULTAT = RESU, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'BALL_TOP',
                                 RESULTANTE = { 'DX' }, OPERATION = 'EXTRACTION', NUME_ORDRE = 3 } }
local Q = math.abs(TQ['DX'][1])
local C_OVER_A = math.sqrt(1.0 - Q / (MU * P))

local function status(node, calc, refe)
  return _F{ RESULTAT = RESU, NUME_ORDRE = 3, NOM_CHAM = 'CONT_NOEU', NOM_CMP = 'CONT', NOEUD = node, VALE_CALC = calc,
             REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, CRITERE = 'ABSOLU', PRECISION = 0.0 }
end
TEST_RESU{ RESU = {
  _F{ RESULTAT = RESU, NUME_ORDRE = 3, NOM_CHAM = 'DEPL', GROUP_NO = 'O_BLOCK', NOM_CMP = 'LAGS_C', VALE_CALC = -1.105747629e+07,
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -2.0 * P / (math.pi * A), PRECISION = 1e-2 },
  _F{ RESULTAT = RESU, NUME_ORDRE = 3, NOM_CHAM = 'DEPL', GROUP_NO = 'O_BLOCK', NOM_CMP = 'LAGS_F1', VALE_CALC = -4.666743440e-01,
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -(1.0 - C_OVER_A), PRECISION = 1e-2 },
  status('N1103', 1, 1), status('N3071', 1, 1),  -- x = +-0.0175 m: stick
  status('N1109', 2, 2), status('N3077', 2, 2),  -- x = +-0.025 m: slip
} }
-- The tangential force itself, and so Q / (mu P) = 0.714 (a non-regression value of the run).
TEST_TABLE{ TABLE = TQ, NOM_PARA = 'DX', VALE_CALC = 9.861705558e+04 }
FIN()
