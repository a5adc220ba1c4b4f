-- Pressurised ring fitted in a sleeve (plane strain, Lame solution): mortar contact on a curved,
-- non-matching interface, QUAD8 cells (arc edges curved, every node on its circle).
-- Purpose: DEFI_CONT APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN' between curved SEG3 cells that
--          do not match (48 on the ring's outer arc RING_OUT = slave, 40 on the sleeve's inner arc
--          SLEEVE_IN = master), slave end nodes on the symmetry lines (one displacement component
--          imposed, the other one carrying the contact condition).
-- Geometry (metres): quarter of a ring a = 0.5 <= r <= b = 0.75 (RING, 48 x 8 QUAD8) fitted without
--          gap or interference in a sleeve b <= r <= c = 1 (SLEEVE, 40 x 8 QUAD8), meshed independently;
--          lunaster-meshgen --ring quad8:48x8 --sleeve quad8:40x8 (tools/make_meshes.sh).
-- Loads: pressure p = 1e8 Pa on r = a (INNER), r = c free, DX = 0 on x = 0, DY = 0 on y = 0;
--          ring E1 = 2e11 Pa, nu1 = 0.3; sleeve E2 = 1e11 Pa, nu2 = 0.25; frictionless contact on r = b.
-- Reference: analytical (Lame). In each body u_r = A r + B / r; for a cylinder ri <= r <= ro under
--          pressures pi inside and po outside, sigma_rr = C1 - C2 / r^2, sigma_tt = C1 + C2 / r^2 with
--          C1 = (pi ri^2 - po ro^2) / (ro^2 - ri^2), C2 = (pi - po) ri^2 ro^2 / (ro^2 - ri^2), and in plane
--          strain u_r = (1 + nu) / E r ((1 - 2 nu) C1 + C2 / r^2). Ring: pi = p, po = q; sleeve: pi = q,
--          po = 0; sigma_rr = -q on both sides of r = b, and u_r(b) equal on both sides gives
--            q = [2 (1 - nu1^2) / E1 a^2 p / (b^2 - a^2)]
--                / [(1 + nu1) / E1 ((1 - 2 nu1) b^2 + a^2) / (b^2 - a^2) + (1 + nu2) / E2 ((1 - 2 nu2) b^2 + c^2) / (c^2 - b^2)]
--            = 1.5660243999877e7 Pa > 0 (the contact stays closed everywhere): LAGS_C = -q on RING_OUT;
--          u_r(b) = 4.299575919609e-4 m (DX at P_X, DY at P_Y, DX at Q_X), u_r(a) = 5.607426016410e-4 m
--          (DY at A_Y), u_r(c) = 3.775237392827e-4 m (DX at C_X). The sum of LAGS_C over the 97 slave
--          nodes is -97 q.
-- REAC_GEOM = 'SANS': the Lame solution is small-strain, so the pairing stays in the reference
--          configuration. With the default 'AUTOMATIQUE' the pairing is redone in the deformed
--          configuration and LAGS_C becomes a force per deformed length, q b / (b + u_r(b)):
--          5.73e-4 below q, the floor the pressure error then reaches (tests/bench/README.md).
-- Convergence (tests/bench/ring_convergence.sh: ring quad8:12x2 on sleeve quad8:10x2 refined k = 1 ..
--          32, h = slave cell arc 0.098 .. 0.0031 m): largest nodal pressure error over the slave
--          nodes 1.6e-1, 2.0e-2, 2.5e-3, 3.1e-4, 3.7e-5, 4.2e-6: O(h^3.0) (least-squares slope 3.05);
--          arc-mean pressure O(h^4); radial displacement of the slave nodes O(h^4). This deck is k = 4.
-- Where we stand (k = 4): LAGS_C within 1.3e-3 (MIN) and 2.6e-3 (MAX) of -q, 7.9e-4 at the end
--          nodes P_X and P_Y (no outliers); displacements within 4e-6. Runtime label: fast, contact,
--          mortar.
DEBUT()
local p, q = 1.0e8, 1.5660243999877e+07
local ub, ua, uc = 4.299575919609e-04, 5.607426016410e-04, 3.775237392827e-04
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
RING = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
SLEEVE = DEFI_MATERIAU{ ELAS = _F{ E = 1.0e11, NU = 0.25 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'RING', MATER = RING },
                                               _F{ GROUP_MA = 'SLEEVE', MATER = SLEEVE } } }
CHA = AFFE_CHAR_MECA{ MODELE = MO,
                      DDL_IMPO = { _F{ GROUP_NO = { 'X0_RING', 'X0_SLEEVE' }, DX = 0.0 },
                                   _F{ GROUP_NO = { 'Y0_RING', 'Y0_SLEEVE' }, DY = 0.0 } },
                      PRES_REP = _F{ GROUP_MA = 'INNER', PRES = p } }
CONT = DEFI_CONT{ MODELE = MO, REAC_GEOM = 'SANS',
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'RING_OUT', GROUP_MA_MAIT = 'SLEEVE_IN',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'OUI' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                      CONVERGENCE = _F{ RESI_GLOB_RELA = 1.0e-8 } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6);
-- PRECISION: the error measured against the Lame value, rounded up.
local function t(group, cmp, kind, refe, precision, calc)
  return _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = group, NOM_CMP = cmp, TYPE_TEST = kind,
             REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = precision, VALE_CALC = calc }
end
TEST_RESU{ RESU = {
  t('RING_OUT', 'LAGS_C', 'MIN', -q, 1.3e-3, -1.567926280647e+07),         -- measured 1.21e-3
  t('RING_OUT', 'LAGS_C', 'MAX', -q, 2.6e-3, -1.562091759793e+07),         -- measured 2.51e-3
  t('P_X', 'LAGS_C', nil, -q, 8.5e-4, -1.567264006656e+07),                 -- measured 7.92e-4
  t('P_Y', 'LAGS_C', nil, -q, 8.5e-4, -1.567264006711e+07),                 -- measured 7.92e-4
  t('RING_OUT', 'LAGS_C', 'SOMM', -97 * q, 3.0e-4, -1.518621589978e+09),  -- measured 2.78e-4
  t('P_X', 'DX', nil, ub, 1.6e-6, 4.299569487997e-04),                   -- measured 1.50e-6
  t('P_Y', 'DY', nil, ub, 1.6e-6, 4.299569487996e-04),                   -- measured 1.50e-6
  t('Q_X', 'DX', nil, ub, 3.6e-6, 4.299591000748e-04),                   -- measured 3.51e-6
  t('A_Y', 'DY', nil, ua, 7.0e-7, 5.607422446084e-04),                   -- measured 6.37e-7
  t('C_X', 'DX', nil, uc, 1.6e-6, 3.775243249713e-04),                   -- measured 1.55e-6
} }
FIN()
