-- Mortar contact patch test in a rotated frame, 2D: the SSNP121 A scene (slave AB, 12 SEG2, on master
-- EF, 11 SEG2, non-matching; CONTACT_INIT='NON') turned by 30 degrees about the origin with
-- MODI_MAILLAGE ROTATION. CD moves by 0.1 along the rotated vertical (DX and DY both imposed), GH is
-- fixed.
-- Purpose: mortar contact (DEFI_CONT, APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN') on an interface
--          along no coordinate axis: the normals, the weighted gaps and the elimination of one
--          displacement component per active slave node must not depend on the frame.
-- Reference: analytical, the solution of SSNP121 turned by 30 degrees: LAGS_C = -1e5 Pa everywhere on
--            AB; interface displacement -0.05 n with n = (-sin 30, cos 30) the rotated vertical,
--            DX = 0.025 m, DY = -0.0433 m on AB and EF; stress -1e5 n n^T (SIXX = -2.5e4,
--            SIYY = -7.5e4, SIXY = 4.33e4 Pa). Every check at 1e-8. Units SI.
-- What we get: every value within 2.8e-14 (relative) of the analytical one.
-- Runtime label: fast, contact.
DEBUT()
local ANGLE = 30.0                                          -- degrees, counter-clockwise about z
local s, c = math.sin(math.rad(ANGLE)), math.cos(math.rad(ANGLE))
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ROTATION = _F{ POIN_1 = { 0.0, 0.0 }, ANGLE = ANGLE } }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.1 * s, DY = -0.1 * c },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
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
  ['DEPL LAGS_C A'] = -1.000000000000e+05,
  ['DEPL DX A'] = 2.500000000000e-02,
  ['DEPL DY A'] = -4.330127018922e-02,
  ['DEPL LAGS_C O'] = -1.000000000000e+05,
  ['DEPL DX O'] = 2.500000000000e-02,
  ['DEPL DY O'] = -4.330127018922e-02,
  ['DEPL LAGS_C B'] = -1.000000000000e+05,
  ['DEPL DX B'] = 2.500000000000e-02,
  ['DEPL DY B'] = -4.330127018922e-02,
  ['DEPL LAGS_C MIN(AB)'] = -1.000000000000e+05,
  ['DEPL DX MIN(AB)'] = 2.500000000000e-02,
  ['DEPL DY MIN(AB)'] = -4.330127018922e-02,
  ['SIGM_NOEU SIXX MIN(AB)'] = -2.500000000000e+04,
  ['SIGM_NOEU SIYY MIN(AB)'] = -7.500000000000e+04,
  ['SIGM_NOEU SIXY MIN(AB)'] = 4.330127018922e+04,
  ['DEPL DX MIN(EF)'] = 2.500000000000e-02,
  ['DEPL DY MIN(EF)'] = -4.330127018922e-02,
  ['SIGM_NOEU SIXX MIN(EF)'] = -2.500000000000e+04,
  ['SIGM_NOEU SIYY MIN(EF)'] = -7.500000000000e+04,
  ['SIGM_NOEU SIXY MIN(EF)'] = 4.330127018922e+04,
  ['DEPL LAGS_C MAX(AB)'] = -1.000000000000e+05,
  ['DEPL DX MAX(AB)'] = 2.500000000000e-02,
  ['DEPL DY MAX(AB)'] = -4.330127018922e-02,
  ['SIGM_NOEU SIXX MAX(AB)'] = -2.500000000000e+04,
  ['SIGM_NOEU SIYY MAX(AB)'] = -7.500000000000e+04,
  ['SIGM_NOEU SIXY MAX(AB)'] = 4.330127018922e+04,
  ['DEPL DX MAX(EF)'] = 2.500000000000e-02,
  ['DEPL DY MAX(EF)'] = -4.330127018922e-02,
  ['SIGM_NOEU SIXX MAX(EF)'] = -2.500000000000e+04,
  ['SIGM_NOEU SIYY MAX(EF)'] = -7.500000000000e+04,
  ['SIGM_NOEU SIXY MAX(EF)'] = 4.330127018922e+04,
}

local checks = require('lib.mortar_checks').new(RESU, calc)
local check = checks.check
-- The analytical solution turned by ANGLE: the rotated vertical is n = (-s, c); the interface moves
-- by -0.05 n, the stress is -1e5 n n^T.
local u = { DX = 0.05 * s, DY = -0.05 * c }
local sigma = { SIXX = -1.0e5 * s * s, SIYY = -1.0e5 * c * c, SIXY = 1.0e5 * s * c }
for _, point in ipairs({ 'A', 'O', 'B' }) do
  check('DEPL', 'LAGS_C', -1.0e5, point)
  for _, cmp in ipairs({ 'DX', 'DY' }) do check('DEPL', cmp, u[cmp], point) end
end
for _, kind in ipairs({ 'MIN', 'MAX' }) do
  check('DEPL', 'LAGS_C', -1.0e5, 'AB', kind)
  for _, group in ipairs({ 'AB', 'EF' }) do
    for _, cmp in ipairs({ 'DX', 'DY' }) do check('DEPL', cmp, u[cmp], group, kind) end
    for _, cmp in ipairs({ 'SIXX', 'SIYY', 'SIXY' }) do check('SIGM_NOEU', cmp, sigma[cmp], group, kind) end
  end
end
TEST_RESU{ RESU = checks.list }
FIN()
