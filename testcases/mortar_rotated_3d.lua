-- Mortar contact patch test in a rotated frame, 3D: the SSNP121 I scene (V1 = [0,1]^3 5x5x1 HEXA8,
-- slave SURESC: 25 QUAD4; V2 = [0,1]^2 x [1,2] 4x4x1 HEXA20, master SURMAI: 16 QUAD8; non-matching)
-- turned by 40 degrees about the axis through (0.5, 0.5, 1) with direction (1, 2, 3) (MODI_MAILLAGE
-- ROTATION). ENCAST is clamped, SURCHA moves by 0.1 along the rotated vertical n (DX, DY, DZ imposed).
-- Purpose: mortar contact (DEFI_CONT, APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN', CONTACT_INIT='NON')
--          on an interface along no coordinate plane: the auxiliary planes, the clipping and the
--          elimination of one displacement component per active slave node must not depend on the frame.
-- Reference: analytical, the solution of SSNP121 turned: LAGS_C = -1e5 Pa on the whole interface,
--            interface displacement -0.05 n (all three components, on SURESC and SURMAI), stress
--            -1e5 n n^T (all six components); n = (0.3937, -0.0715, 0.9164). Every check at 1e-8.
--            Units SI.
-- What we get: every value within 1e-12 (relative) of the analytical one but the small SIYY (-511 Pa),
-- 3.8e-12 relative, i.e. 2e-9 Pa, round-off of the 1e5 Pa stress.
-- Runtime label: fast, contact, 3D.
DEBUT()
-- The rotation: ANGLE degrees about the axis through P with direction K (unit), Rodrigues' formula.
local ANGLE, P, K = 40.0, { 0.5, 0.5, 1.0 }, { 1.0, 2.0, 3.0 }
local norm = math.sqrt(K[1] ^ 2 + K[2] ^ 2 + K[3] ^ 2)
local k = { K[1] / norm, K[2] / norm, K[3] / norm }
local cs, sn = math.cos(math.rad(ANGLE)), math.sin(math.rad(ANGLE))
-- n = R e_z = cos e_z + sin (k x e_z) + (1 - cos) k_z k: the rotated vertical
local n = { sn * k[2] + (1 - cs) * k[3] * k[1], -sn * k[1] + (1 - cs) * k[3] * k[2], cs + (1 - cs) * k[3] * k[3] }
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121i.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ROTATION = _F{ POIN_1 = P, DIR = K, ANGLE = ANGLE } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = -0.1 * n[1], DY = -0.1 * n[2], DZ = -0.1 * n[3] } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6), keyed by
-- 'field component point' or 'field component MIN(group)'.
local calc = {
  ['DEPL LAGS_C A21'] = -1.000000000000e+05,
  ['DEPL DX A21'] = -1.968588816594e-02,
  ['DEPL DY A21'] = 3.576277380801e-03,
  ['DEPL DZ A21'] = -4.582222219855e-02,
  ['DEPL LAGS_C A22'] = -1.000000000000e+05,
  ['DEPL DX A22'] = -1.968588816594e-02,
  ['DEPL DY A22'] = 3.576277380801e-03,
  ['DEPL DZ A22'] = -4.582222219855e-02,
  ['DEPL LAGS_C A23'] = -1.000000000000e+05,
  ['DEPL DX A23'] = -1.968588816594e-02,
  ['DEPL DY A23'] = 3.576277380801e-03,
  ['DEPL DZ A23'] = -4.582222219855e-02,
  ['DEPL LAGS_C A24'] = -9.999999999999e+04,
  ['DEPL DX A24'] = -1.968588816594e-02,
  ['DEPL DY A24'] = 3.576277380801e-03,
  ['DEPL DZ A24'] = -4.582222219855e-02,
  ['DEPL LAGS_C MIN(SURESC)'] = -1.000000000000e+05,
  ['DEPL DX MIN(SURESC)'] = -1.968588816594e-02,
  ['DEPL DY MIN(SURESC)'] = 3.576277380801e-03,
  ['DEPL DZ MIN(SURESC)'] = -4.582222219855e-02,
  ['SIGM_NOEU SIXX MIN(SURESC)'] = -1.550136771528e+04,
  ['SIGM_NOEU SIYY MIN(SURESC)'] = -5.115903961780e+02,
  ['SIGM_NOEU SIZZ MIN(SURESC)'] = -8.398704188855e+04,
  ['SIGM_NOEU SIXY MIN(SURESC)'] = 2.816087862753e+03,
  ['SIGM_NOEU SIXZ MIN(SURESC)'] = -3.608204566863e+04,
  ['SIGM_NOEU SIYZ MIN(SURESC)'] = 6.554919071467e+03,
  ['DEPL DX MIN(SURMAI)'] = -1.968588816594e-02,
  ['DEPL DY MIN(SURMAI)'] = 3.576277380801e-03,
  ['DEPL DZ MIN(SURMAI)'] = -4.582222219855e-02,
  ['SIGM_NOEU SIXX MIN(SURMAI)'] = -1.550136771528e+04,
  ['SIGM_NOEU SIYY MIN(SURMAI)'] = -5.115903961784e+02,
  ['SIGM_NOEU SIZZ MIN(SURMAI)'] = -8.398704188855e+04,
  ['SIGM_NOEU SIXY MIN(SURMAI)'] = 2.816087862751e+03,
  ['SIGM_NOEU SIXZ MIN(SURMAI)'] = -3.608204566863e+04,
  ['SIGM_NOEU SIYZ MIN(SURMAI)'] = 6.554919071465e+03,
  ['DEPL LAGS_C MAX(SURESC)'] = -9.999999999998e+04,
  ['DEPL DX MAX(SURESC)'] = -1.968588816594e-02,
  ['DEPL DY MAX(SURESC)'] = 3.576277380801e-03,
  ['DEPL DZ MAX(SURESC)'] = -4.582222219855e-02,
  ['SIGM_NOEU SIXX MAX(SURESC)'] = -1.550136771528e+04,
  ['SIGM_NOEU SIYY MAX(SURESC)'] = -5.115903961766e+02,
  ['SIGM_NOEU SIZZ MAX(SURESC)'] = -8.398704188854e+04,
  ['SIGM_NOEU SIXY MAX(SURESC)'] = 2.816087862756e+03,
  ['SIGM_NOEU SIXZ MAX(SURESC)'] = -3.608204566862e+04,
  ['SIGM_NOEU SIYZ MAX(SURESC)'] = 6.554919071472e+03,
  ['DEPL DX MAX(SURMAI)'] = -1.968588816594e-02,
  ['DEPL DY MAX(SURMAI)'] = 3.576277380801e-03,
  ['DEPL DZ MAX(SURMAI)'] = -4.582222219855e-02,
  ['SIGM_NOEU SIXX MAX(SURMAI)'] = -1.550136771528e+04,
  ['SIGM_NOEU SIYY MAX(SURMAI)'] = -5.115903961752e+02,
  ['SIGM_NOEU SIZZ MAX(SURMAI)'] = -8.398704188854e+04,
  ['SIGM_NOEU SIXY MAX(SURMAI)'] = 2.816087862756e+03,
  ['SIGM_NOEU SIXZ MAX(SURMAI)'] = -3.608204566862e+04,
  ['SIGM_NOEU SIYZ MAX(SURMAI)'] = 6.554919071474e+03,
}

local checks = require('lib.mortar_checks').new(RESU, calc)
local check = checks.check
-- The analytical solution turned: the interface moves by -0.05 n, the stress is -1e5 n n^T.
local u = { DX = -0.05 * n[1], DY = -0.05 * n[2], DZ = -0.05 * n[3] }
local sigma = { SIXX = -1.0e5 * n[1] * n[1], SIYY = -1.0e5 * n[2] * n[2], SIZZ = -1.0e5 * n[3] * n[3],
                SIXY = -1.0e5 * n[1] * n[2], SIXZ = -1.0e5 * n[1] * n[3], SIYZ = -1.0e5 * n[2] * n[3] }
for _, point in ipairs({ 'A21', 'A22', 'A23', 'A24' }) do
  check('DEPL', 'LAGS_C', -1.0e5, point)
  for _, cmp in ipairs({ 'DX', 'DY', 'DZ' }) do check('DEPL', cmp, u[cmp], point) end
end
for _, kind in ipairs({ 'MIN', 'MAX' }) do
  check('DEPL', 'LAGS_C', -1.0e5, 'SURESC', kind)
  for _, group in ipairs({ 'SURESC', 'SURMAI' }) do
    for _, cmp in ipairs({ 'DX', 'DY', 'DZ' }) do check('DEPL', cmp, u[cmp], group, kind) end
    for _, cmp in ipairs({ 'SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ' }) do
      check('SIGM_NOEU', cmp, sigma[cmp], group, kind)
    end
  end
end
TEST_RESU{ RESU = checks.list }
FIN()
