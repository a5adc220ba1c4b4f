-- Coulomb friction, 3D: the frictional patch test of two elastic cubes, stick and slip.
-- Mesh: lunaster-meshgen --v1 hexa8:4x4x4 --v2 hexa8:4x4x4 --x-faces -o friction_patch_3d.med
-- (SSNP121's cubes: V2 = [0,1]^2x[1,2] on V1 = [0,1]^3, matching on z = 1: slave SURESC, V1's top,
-- master SURMAI; X0_*/X1_* the sides x = 0 and x = 1). 3D, E = 2e11 Pa, NU = 0; ENCAST (z = 0) fixed.
-- Loads: V2 pressed by p = 1e6 Pa on SURCHA (t in [0, 1]); then (t in [1, 2])
--   stick: pushed by a traction tau0 = 1.5e5 Pa = mu p / 2 along x on SURCHA, or
--   slip:  dragged by DX = 1e-5 m imposed on SURCHA (the uniform state needs 2 tau/G = 6e-6 m),
-- with the shear tau (tau0, or mu p) on the sides x = 0, 1 (FORCE_FACE FZ = -+tau, the traction of
-- sigma_xz = tau there), so that sigma_zz = -p, sigma_xz = tau is the exact solution in both cubes.
-- Reference (analytical): LAGS_C = -p; SIXZ = tau; stick: no slip (DX at A21, on V1's top, and
-- the same point of V2 both tau0/G = 1.5e-6 m, G = E/2), code_aster's semi-multipliers (the
-- traction over mu p, in the point's tangent frame t1 = x, t2 = n x t1) LAGS_F1 = -0.5, LAGS_F2 = 0,
-- CONT = 1; slip: LAGS_F1 = -1, LAGS_F2 = 0, CONT = 2, the reaction along x on SURCHA mu p A =
-- 3e5 N (A = 1 m2) and the slave's DX tau/G = 3e-6 m (V1 does not slide).
-- Tolerances: stick is exact (1e-8). In slip V2 slides 4e-6 m and the pairing follows it, moving the
-- master's edges by 1.6e-5 of a cell over the slave's: near the edges the state is no longer
-- exactly uniform (up to 3.7e-5 seen: 5e-5); the slip stays along x (LAGS_F2 within 1e-8) and the
-- reaction is mu p A to round-off.
-- DISCRETE (penalty springs): V2 held by DZ imposed on SURCHA (no CONTACT_INIT there); in full slip
-- the reaction along x on SURCHA is mu times the one along z, exactly (Coulomb's law on the run's
-- own normal force).
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
local mu, p, d, tau0, G = 0.3, 1.0e6, 1.0e-5, 1.5e5, 1.0e11
FIX = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 } }
PRESS = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'SURCHA', PRES = p } }
TOP = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'SURCHA', DZ = -1.0e-5 } }
PUSH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'SURCHA', DX = d } }
SLIDE = AFFE_CHAR_MECA{ MODELE = MO, FORCE_FACE = { _F{ GROUP_MA = { 'X1_V1', 'X1_V2' }, FZ = mu * p },
                                                   _F{ GROUP_MA = { 'X0_V1', 'X0_V2' }, FZ = -mu * p } } }
HOLD = AFFE_CHAR_MECA{ MODELE = MO, FORCE_FACE = { _F{ GROUP_MA = { 'X1_V1', 'X1_V2' }, FZ = tau0 },
                                                  _F{ GROUP_MA = { 'X0_V1', 'X0_V2' }, FZ = -tau0 },
                                                  _F{ GROUP_MA = 'SURCHA', FX = tau0 } } }
L_INST = DEFI_LIST_REEL{ VALE = { 0.0, 1.0, 1.1, 1.5, 2.0 } }
R1 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0, 2.0, 1.0 } }
R2 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 2.0, 1.0 } }
R3 = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 0.0, 1.1, 1.0, 2.0, 1.0 } }

local run, check = require('lib.friction_patch').runner{
  MO = MO, CHMAT = CHMAT, FIX = FIX, PRESS = PRESS, TOP = TOP, PUSH = PUSH, SLIDE = SLIDE, HOLD = HOLD,
  R1 = R1, R2 = R2, R3 = R3, L_INST = L_INST, LAST = 4, SLAVE = 'SURESC', MASTER = 'SURMAI', MU = mu,
  TOP_GROUP = 'SURCHA', REACTIONS = { 'DX', 'DZ' } }

STD_SLIP, T_STD_SLIP = run('CONTINUE', {}, 'slip')
STD_STICK, T_STD_STICK = run('CONTINUE', {}, 'stick')
DIS_SLIP, T_DIS_SLIP = run('DISCRETE', { ALGO_CONT = 'PENALISATION', E_N = 1e14, E_T = 1e13 }, 'slip')

TEST_RESU{ RESU = {
  check(STD_SLIP, 'DEPL', 'A21', 'LAGS_C', -p, -9.999730372e+05, 5e-5),
  check(STD_SLIP, 'DEPL', 'A23', 'LAGS_C', -p, -1.000015205e+06, 5e-5),
  check(STD_SLIP, 'DEPL', 'A21', 'LAGS_F1', -1.0, -1.000000000e+00, 1e-8),
  check(STD_SLIP, 'DEPL', 'A23', 'LAGS_F2', 0.0, -3.256119312e-10, 1e-8, 'ABSOLU'),
  check(STD_SLIP, 'CONT_NOEU', 'A22', 'CONT', 2.0, 2.000000000e+00, 1e-12),
  check(STD_SLIP, 'DEPL', 'A21', 'DX', mu * p / G, 3.000091876e-06, 5e-5),
  check(STD_SLIP, 'SIGM_NOEU', 'A24', 'SIXZ', mu * p, 2.999889584e+05, 5e-5),
  check(STD_STICK, 'DEPL', 'A21', 'LAGS_C', -p, -1.000000000e+06, 1e-8),
  check(STD_STICK, 'DEPL', 'A23', 'LAGS_F1', -tau0 / (mu * p), -5.000000000e-01, 1e-8),
  check(STD_STICK, 'DEPL', 'A23', 'LAGS_F2', 0.0, 9.381984886e-16, 1e-8, 'ABSOLU'),
  check(STD_STICK, 'CONT_NOEU', 'A22', 'CONT', 1.0, 1.000000000e+00, 1e-12),
  check(STD_STICK, 'DEPL', 'A21', 'DX', tau0 / G, 1.500000000e-06, 1e-8),
  check(STD_STICK, 'SIGM_NOEU', 'A24', 'SIXZ', tau0, 1.500000000e+05, 1e-8),
  check(DIS_SLIP, 'CONT_NOEU', 'A22', 'CONT', 2.0, 2.000000000e+00, 1e-12),
} }
local function reaction(tab, refe, calc, tol)
  return _F{ TABLE = tab, NOM_PARA = 'DX', VALE_CALC = calc, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = tol }
end
TEST_TABLE( reaction(T_STD_SLIP, mu * p, 3.000000000e+05, 1e-8) )
TEST_TABLE( reaction(T_DIS_SLIP, -mu * T_DIS_SLIP['DZ'][1], 2.999856451e+05, 1e-8) )
FIN()
