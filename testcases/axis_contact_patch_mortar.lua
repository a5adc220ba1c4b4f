-- Axisymmetric (AXIS) contact patch test with mortar contact (DEFI_CONT, APPARIEMENT='MORTAR'):
-- two coaxial cylinders (x = r, y = axis) stacked along the axis and pressed together: the SSNP121
-- blocks on 0 <= r <= 1 (touching the axis; QUAD4 matching 8/8, non-matching 12/11, QUAD8
-- non-matching 5/4) and on 1 <= r <= 2 (annuli, QUAD4 non-matching 12/11); slave AB (upper),
-- master EF (lower). DY = -0.1 on the top CD, 0 on the bottom GH, DX = 0 on both (and on the axis).
-- NU = 0: the exact state is a uniform axial strain -0.05, SIYY = E eps = -1e5 Pa, no radial or
-- hoop stress, DY = -0.05 on the interface.
-- The mortar integrals use the AXIS measure r dl (per radian), like the elements: with it the
-- dual-basis mortar reproduces the uniform contact pressure to round-off on non-matching meshes;
-- LAGS_C is that pressure (negative in compression). Without the r weight LAGS_C would vary along
-- the interface (it would be the consistent nodal force divided by an unweighted length).
-- LAGRANGIEN: every value at 1e-8 against the analytical one. PENALISATION (COEF_CONT = 1e12 Pa/m):
-- the penalised solution is exact and uniform too: 0.1 = 2 p / E + p / COEF_CONT, so
-- p = 0.1 E / (2 + E / COEF_CONT); SIYY = -p, DY = -0.1 + p / E on AB and -p / E on EF (mortar
-- penalty has no LAGS_C); at 1e-8 as well. What we get: see the VALE_CALC (round-off).
-- Reference: analytical (uniform state). Units SI. Runtime label: fast, contact.
DEBUT()
local E, COEF = 2.0e6, 1.0e12
local P = { LAGRANGIEN = 0.1 * E / 2, PENALISATION = 0.1 * E / (2 + E / COEF) }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6), keyed by
-- 'mesh algorithm field component TYPE_TEST(group)'.
local calc = {
  ['matching LAGRANGIEN DEPL LAGS_C MIN(AB)'] = -1.000000000000e+05,
  ['matching LAGRANGIEN DEPL DY MIN(AB)'] = -5.000000000000e-02,
  ['matching LAGRANGIEN DEPL DY MIN(EF)'] = -5.000000000000e-02,
  ['matching LAGRANGIEN SIGM_NOEU SIYY MIN'] = -1.000000000000e+05,
  ['matching LAGRANGIEN DEPL LAGS_C MAX(AB)'] = -1.000000000000e+05,
  ['matching LAGRANGIEN DEPL DY MAX(AB)'] = -5.000000000000e-02,
  ['matching LAGRANGIEN DEPL DY MAX(EF)'] = -5.000000000000e-02,
  ['matching LAGRANGIEN SIGM_NOEU SIYY MAX'] = -1.000000000000e+05,
  ['matching PENALISATION DEPL DY MIN(AB)'] = -5.000005000034e-02,
  ['matching PENALISATION DEPL DY MIN(EF)'] = -4.999995000044e-02,
  ['matching PENALISATION SIGM_NOEU SIYY MIN'] = -9.999990001492e+04,
  ['matching PENALISATION DEPL DY MAX(AB)'] = -5.000004999783e-02,
  ['matching PENALISATION DEPL DY MAX(EF)'] = -4.999994999793e-02,
  ['matching PENALISATION SIGM_NOEU SIYY MAX'] = -9.999989998528e+04,
  ['nonmatching LAGRANGIEN DEPL LAGS_C MIN(AB)'] = -1.000000000000e+05,
  ['nonmatching LAGRANGIEN DEPL DY MIN(AB)'] = -5.000000000000e-02,
  ['nonmatching LAGRANGIEN DEPL DY MIN(EF)'] = -5.000000000000e-02,
  ['nonmatching LAGRANGIEN SIGM_NOEU SIYY MIN'] = -1.000000000000e+05,
  ['nonmatching LAGRANGIEN DEPL LAGS_C MAX(AB)'] = -1.000000000000e+05,
  ['nonmatching LAGRANGIEN DEPL DY MAX(AB)'] = -5.000000000000e-02,
  ['nonmatching LAGRANGIEN DEPL DY MAX(EF)'] = -5.000000000000e-02,
  ['nonmatching LAGRANGIEN SIGM_NOEU SIYY MAX'] = -1.000000000000e+05,
  ['nonmatching PENALISATION DEPL DY MIN(AB)'] = -5.000005000025e-02,
  ['nonmatching PENALISATION DEPL DY MIN(EF)'] = -4.999995000035e-02,
  ['nonmatching PENALISATION SIGM_NOEU SIYY MIN'] = -9.999990002129e+04,
  ['nonmatching PENALISATION DEPL DY MAX(AB)'] = -5.000004999763e-02,
  ['nonmatching PENALISATION DEPL DY MAX(EF)'] = -4.999994999760e-02,
  ['nonmatching PENALISATION SIGM_NOEU SIYY MAX'] = -9.999989997770e+04,
  ['nonmatching_quad8 LAGRANGIEN DEPL LAGS_C MIN(AB)'] = -1.000000000000e+05,
  ['nonmatching_quad8 LAGRANGIEN DEPL DY MIN(AB)'] = -5.000000000000e-02,
  ['nonmatching_quad8 LAGRANGIEN DEPL DY MIN(EF)'] = -5.000000000000e-02,
  ['nonmatching_quad8 LAGRANGIEN SIGM_NOEU SIYY MIN'] = -1.000000000000e+05,
  ['nonmatching_quad8 LAGRANGIEN DEPL LAGS_C MAX(AB)'] = -1.000000000000e+05,
  ['nonmatching_quad8 LAGRANGIEN DEPL DY MAX(AB)'] = -5.000000000000e-02,
  ['nonmatching_quad8 LAGRANGIEN DEPL DY MAX(EF)'] = -5.000000000000e-02,
  ['nonmatching_quad8 LAGRANGIEN SIGM_NOEU SIYY MAX'] = -1.000000000000e+05,
  ['nonmatching_quad8 PENALISATION DEPL DY MIN(AB)'] = -5.000005000207e-02,
  ['nonmatching_quad8 PENALISATION DEPL DY MIN(EF)'] = -4.999995000208e-02,
  ['nonmatching_quad8 PENALISATION SIGM_NOEU SIYY MIN'] = -9.999990000993e+04,
  ['nonmatching_quad8 PENALISATION DEPL DY MAX(AB)'] = -5.000005000030e-02,
  ['nonmatching_quad8 PENALISATION DEPL DY MAX(EF)'] = -4.999994999994e-02,
  ['nonmatching_quad8 PENALISATION SIGM_NOEU SIYY MAX'] = -9.999989998922e+04,
  ['nonmatching_away LAGRANGIEN DEPL LAGS_C MIN(AB)'] = -1.000000000000e+05,
  ['nonmatching_away LAGRANGIEN DEPL DY MIN(AB)'] = -5.000000000000e-02,
  ['nonmatching_away LAGRANGIEN DEPL DY MIN(EF)'] = -5.000000000000e-02,
  ['nonmatching_away LAGRANGIEN SIGM_NOEU SIYY MIN'] = -1.000000000000e+05,
  ['nonmatching_away LAGRANGIEN DEPL LAGS_C MAX(AB)'] = -1.000000000000e+05,
  ['nonmatching_away LAGRANGIEN DEPL DY MAX(AB)'] = -5.000000000000e-02,
  ['nonmatching_away LAGRANGIEN DEPL DY MAX(EF)'] = -5.000000000000e-02,
  ['nonmatching_away LAGRANGIEN SIGM_NOEU SIYY MAX'] = -1.000000000000e+05,
  ['nonmatching_away PENALISATION DEPL DY MIN(AB)'] = -5.000005000255e-02,
  ['nonmatching_away PENALISATION DEPL DY MIN(EF)'] = -4.999995000275e-02,
  ['nonmatching_away PENALISATION SIGM_NOEU SIYY MIN'] = -9.999990001123e+04,
  ['nonmatching_away PENALISATION DEPL DY MAX(AB)'] = -5.000005000071e-02,
  ['nonmatching_away PENALISATION DEPL DY MAX(EF)'] = -4.999995000060e-02,
  ['nonmatching_away PENALISATION SIGM_NOEU SIYY MAX'] = -9.999989998839e+04,
}

local checks = {}
local function check(resu, label, field, cmp, kind, group, refe, scale)
  local key = label .. ' ' .. field .. ' ' .. cmp .. ' ' .. kind .. (group and '(' .. group .. ')' or '')
  local f = _F{ RESULTAT = resu, NUME_ORDRE = 1, NOM_CHAM = field, NOM_CMP = cmp, TYPE_TEST = kind,
                LEGENDE = label }
  -- Values at round-off around a zero reference are checked absolutely only (no VALE_CALC).
  if refe ~= 0.0 then f.VALE_CALC = assert(calc[key], key) end
  if group then f.GROUP_MA = group end
  if refe then
    f.REFERENCE = 'ANALYTIQUE'; f.VALE_REFE = refe; f.PRECISION = 1.0e-8
    if refe == 0.0 then f.CRITERE = 'ABSOLU'; f.PRECISION = 1.0e-8 * scale end
  end
  checks[#checks + 1] = f
end

for _, mesh in ipairs({ 'matching', 'nonmatching', 'nonmatching_quad8', 'nonmatching_away' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/axis_contact_' .. mesh .. '.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
  local CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
  local ddl = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 }, _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } }
  if mesh ~= 'nonmatching_away' then ddl[#ddl + 1] = _F{ GROUP_NO = { 'DA', 'HE' }, DX = 0.0 } end
  local CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = ddl }
  for _, algo in ipairs({ 'LAGRANGIEN', 'PENALISATION' }) do
    local zone = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', ALGO_CONT = algo,
                     CONTACT_INIT = 'NON' }
    if algo == 'PENALISATION' then zone.COEF_CONT = COEF end
    local CONT = DEFI_CONT{ MODELE = MO, ZONE = zone }
    local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                             EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                             COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
    local label = mesh .. ' ' .. algo
    local p = P[algo]
    for _, kind in ipairs({ 'MIN', 'MAX' }) do
      if algo == 'LAGRANGIEN' then check(R, label, 'DEPL', 'LAGS_C', kind, 'AB', -p) end
      check(R, label, 'DEPL', 'DY', kind, 'AB', -0.1 + p / E)
      check(R, label, 'DEPL', 'DY', kind, 'EF', -p / E)
      check(R, label, 'SIGM_NOEU', 'SIYY', kind, nil, -p)
      check(R, label, 'SIGM_NOEU', 'SIZZ', kind, nil, 0.0, p)
      check(R, label, 'SIGM_NOEU', 'SIXX', kind, nil, 0.0, p)
    end
  end
end
TEST_RESU{ RESU = checks }
FIN()
