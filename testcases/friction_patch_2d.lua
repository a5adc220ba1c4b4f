-- Coulomb friction, 2D: the frictional patch test of two elastic blocks, stick and slip, for
-- each friction method of DEFI_CONTACT (FROTTEMENT='COULOMB').
-- Mesh: lunaster-meshgen --upper quad4:8 --lower quad4:8 -o friction_patch_2d.med (SSNP121's
-- blocks, PLAQUE1 = [-1,1]x[0,1] on PLAQUE2 = [-1,1]x[-1,0], matching on y = 0: slave AB, master
-- EF). D_PLAN, E = 2e11 Pa, NU = 0; GH fixed.
-- Loads: the upper block is pressed by p = 1e6 Pa on CD (t in [0, 1]); then (t in [1, 2]) it is
--   stick: pushed by a traction tau0 = 1.5e5 Pa = mu p / 2 along x on CD, or
--   slip:  dragged by DX = 1e-5 m imposed on CD (the uniform state needs only 2 tau/G = 6e-6),
-- with the shear tau (tau0, or mu p in slip) on the four lateral edges (FORCE_CONTOUR FY = +-tau,
-- its traction on x = +-1) so that the uniform state sigma_yy = -p, sigma_xy = tau is the exact
-- solution in both blocks.
-- Reference (analytical): LAGS_C = -p; SIXY = tau everywhere; stick: nothing slips (augmented
-- Lagrangian: DX(A) = DX(E) = tau0/G = 1.5e-6 m, G = E/2; penalty: an elastic slip tau0/COEF_PENA_FROT
-- besides), LAGS_F1 = -tau0/(mu p) = -0.5 (code_aster's semi-multiplier: the traction over mu p; the
-- tangent of the master edge EF points along -x), CONT = 1; slip: LAGS_F1 = -1, CONT = 2, the
-- slave's DX = 1e-5 - tau/G = 7e-6 m, and the reaction on CD is mu p L = 6e5 N (L = 2 m); nodal
-- tangential force at an interior slave node (tributary length 0.25 m) -mu p 0.25 = -7.5e4 N in slip,
-- -tau0 0.25 = -3.75e4 N in stick.
-- Tolerances: the pairing is in the current configuration, so the slip (4e-6 m) moves the ends of
-- the slave edge by 1.6e-5 of a cell over the master's ends: values within 5e-5 of the uniform
-- state (1.3e-5 at B). The stick state has no slip and is exact (1e-8); with the penalties (1e15,
-- 1e14 against the blocks' 2e11) round-off is amplified: 1e-7 (5e-9 seen).
-- DISCRETE (node to segment, penalty springs E_N, E_T): no CONTACT_INIT there, so the upper block is
-- held by DY = -1e-5 m on CD instead of the pressure (a block held only by springs at zero gap is
-- singular at its first iteration, as in code_aster); the normal force then depends on E_N, and the
-- reference is Coulomb's law itself in full slip: the reaction along x on CD is mu times the one
-- along y, exactly (1e-8). Its stick case needs the block held at its first iteration and is not run.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
local mu, p, d, tau0, G = 0.3, 1.0e6, 1.0e-5, 1.5e5, 1.0e11
FIX = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'GH', DX = 0.0, DY = 0.0 } }
PRESS = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'CD', PRES = p } }
TOP = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'CD', DY = -1.0e-5 } }
PUSH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'CD', DX = d } }
SLIDE = AFFE_CHAR_MECA{ MODELE = MO, FORCE_CONTOUR = { _F{ GROUP_MA = { 'BC', 'FG' }, FY = mu * p },
                                                      _F{ GROUP_MA = { 'DA', 'HE' }, FY = -mu * p } } }
HOLD = AFFE_CHAR_MECA{ MODELE = MO, FORCE_CONTOUR = { _F{ GROUP_MA = { 'BC', 'FG' }, FY = tau0 },
                                                     _F{ GROUP_MA = { 'DA', 'HE' }, FY = -tau0 },
                                                     _F{ GROUP_MA = 'CD', FX = tau0 } } }
L_INST = DEFI_LIST_REEL{ VALE = { 0.0, 0.5, 1.0, 1.1, 1.25, 1.5, 1.75, 2.0 } }
R1 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0, 2.0, 1.0 } }
R2 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 2.0, 1.0 } }
R3 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 1.1, 1.0, 2.0, 1.0 } }

local run, check = require('lib.friction_patch').runner{
  MO = MO, CHMAT = CHMAT, FIX = FIX, PRESS = PRESS, TOP = TOP, PUSH = PUSH, SLIDE = SLIDE, HOLD = HOLD,
  R1 = R1, R2 = R2, R3 = R3, L_INST = L_INST, LAST = 7, SLAVE = 'AB', MASTER = 'EF', MU = mu,
  TOP_GROUP = 'CD', REACTIONS = { 'DX', 'DY' } }

-- CONTINUE, augmented Lagrangian friction (ALGO_FROT='STANDARD').
STD_SLIP, T_STD_SLIP = run('CONTINUE', {}, 'slip')
STD_STICK, T_STD_STICK = run('CONTINUE', {}, 'stick')
-- CONTINUE, penalty contact and penalty friction.
local penalty = { ALGO_CONT = 'PENALISATION', COEF_PENA_CONT = 1e15, CONTACT_INIT = 'OUI',
                  ALGO_FROT = 'PENALISATION', COEF_PENA_FROT = 1e14 }
PEN_SLIP, T_PEN_SLIP = run('CONTINUE', penalty, 'slip')
PEN_STICK, T_PEN_STICK = run('CONTINUE', penalty, 'stick')
-- DISCRETE: penalty springs.
DIS_SLIP, T_DIS_SLIP = run('DISCRETE', { ALGO_CONT = 'PENALISATION', E_N = 1e14, E_T = 1e13 }, 'slip')

TEST_RESU{ RESU = {
  -- augmented Lagrangian, slip
  check(STD_SLIP, 'DEPL', 'A', 'LAGS_C', -p, -1.000000718e+06, 5e-5),
  check(STD_SLIP, 'DEPL', 'O', 'LAGS_C', -p, -1.000000194e+06, 5e-5),
  check(STD_SLIP, 'DEPL', 'B', 'LAGS_C', -p, -9.999866326e+05, 5e-5),
  check(STD_SLIP, 'DEPL', 'A', 'LAGS_F1', -1.0, -1.000000000e+00, 1e-8),
  check(STD_SLIP, 'DEPL', 'B', 'LAGS_F1', -1.0, -1.000000000e+00, 1e-8),
  check(STD_SLIP, 'CONT_NOEU', 'O', 'CONT', 2.0, 2.000000000e+00, 1e-12),
  check(STD_SLIP, 'CONT_NOEU', 'O', 'RTGX', -mu * p * 0.25, -7.500001456e+04, 5e-5),
  check(STD_SLIP, 'DEPL', 'O', 'DX', d - mu * p / G, 6.999944971e-06, 5e-5),
  check(STD_SLIP, 'DEPL', 'E', 'DX', mu * p / G, 3.000012175e-06, 5e-5),
  check(STD_SLIP, 'SIGM_NOEU', 'C', 'SIXY', mu * p, 2.999994768e+05, 5e-5),
  check(STD_SLIP, 'SIGM_NOEU', 'H', 'SIXY', mu * p, 3.000001623e+05, 5e-5),
  check(STD_SLIP, 'SIGM_NOEU', 'C', 'SIYY', -p, -9.999996696e+05, 5e-5),
  -- augmented Lagrangian, stick
  check(STD_STICK, 'DEPL', 'O', 'LAGS_C', -p, -1.000000000e+06, 1e-8),
  check(STD_STICK, 'DEPL', 'A', 'LAGS_F1', -tau0 / (mu * p), -5.000000000e-01, 1e-8),
  check(STD_STICK, 'DEPL', 'B', 'LAGS_F1', -tau0 / (mu * p), -5.000000000e-01, 1e-8),
  check(STD_STICK, 'CONT_NOEU', 'O', 'CONT', 1.0, 1.000000000e+00, 1e-12),
  check(STD_STICK, 'CONT_NOEU', 'O', 'RTAX', -tau0 * 0.25, -3.750000000e+04, 1e-8),
  check(STD_STICK, 'DEPL', 'A', 'DX', tau0 / G, 1.500000000e-06, 1e-8),
  check(STD_STICK, 'DEPL', 'E', 'DX', tau0 / G, 1.500000000e-06, 1e-8),
  check(STD_STICK, 'SIGM_NOEU', 'C', 'SIXY', tau0, 1.500000000e+05, 1e-8),
  check(STD_STICK, 'SIGM_NOEU', 'H', 'SIXY', tau0, 1.500000000e+05, 1e-8),
  -- penalty, slip
  check(PEN_SLIP, 'DEPL', 'O', 'LAGS_C', -p, -1.000000194e+06, 5e-5),
  check(PEN_SLIP, 'CONT_NOEU', 'O', 'CONT', 2.0, 2.000000000e+00, 1e-12),
  check(PEN_SLIP, 'CONT_NOEU', 'O', 'RTGX', -mu * p * 0.25, -7.500001456e+04, 5e-5),
  check(PEN_SLIP, 'SIGM_NOEU', 'C', 'SIXY', mu * p, 2.999994768e+05, 5e-5),
  -- penalty, stick: the elastic slip tau0 / COEF_PENA_FROT
  check(PEN_STICK, 'CONT_NOEU', 'O', 'CONT', 1.0, 1.000000000e+00, 1e-12),
  check(PEN_STICK, 'CONT_NOEU', 'O', 'RTAX', -tau0 * 0.25, -3.750000013e+04, 1e-7),
  check(PEN_STICK, 'DEPL', 'A', 'DX', tau0 / G + tau0 / 1e14, 1.501500010e-06, 1e-7),
  check(PEN_STICK, 'SIGM_NOEU', 'H', 'SIXY', tau0, 1.500000001e+05, 1e-7),
  -- discrete, slip
  check(DIS_SLIP, 'CONT_NOEU', 'O', 'CONT', 2.0, 2.000000000e+00, 1e-12),
} }
local function reaction(tab, refe, calc, tol)
  return _F{ TABLE = tab, NOM_PARA = 'DX', VALE_CALC = calc, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = tol }
end
TEST_TABLE( reaction(T_STD_SLIP, mu * p * 2.0, 6.000000000e+05, 1e-8) )
TEST_TABLE( reaction(T_PEN_SLIP, mu * p * 2.0, 6.000000000e+05, 1e-8) )
-- Coulomb's law on the run's own normal force (the springs set it).
TEST_TABLE( reaction(T_DIS_SLIP, -mu * T_DIS_SLIP['DY'][1], 5.998594106e+05, 1e-8) )
FIN()
