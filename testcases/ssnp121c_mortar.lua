-- SSNP121 C with mortar contact: the patch test of ssnp121a_mortar.lua (slave AB, 12 SEG2, on
-- master EF, 11 SEG2, non-matching; CONTACT_INIT='NON') with ALGO_CONT='PENALISATION': the pressure
-- is COEF_CONT (Pa/m) times the penetration of the weighted gaps. code_aster's model C is a
-- node-to-segment penalty with slave EF; here the slave is AB so that LAGS_C is checked at A, O, B.
-- Purpose: the mortar penalty passes the patch test: the penalised solution is exact and uniform.
-- Reference: analytical. The penalised solution: 0.1 = 2 p / E + p / COEF_CONT, so
--            p = 0.1 E / (2 + E / COEF_CONT) = 99999.900000100 Pa for E = 2e6, COEF_CONT = 1e12;
--            LAGS_C = SIYY = -p, DY = -0.1 + p/E on AB and -p/E on EF (they overlap by p/COEF_CONT);
--            all at 1e-8. LAGS_C is also checked against the unpenalised -1e5 with PRECISION =
--            E/(2 COEF_CONT) + 1 % = 1.01e-6: the penalty floor, and no worse. Units SI.
-- What we get: every value within 2.5e-10 of the exact penalised one (COEF_CONT is 5e5 E per metre:
-- the conditioning costs that much round-off), LAGS_C 1.000e-6 from -1e5.
-- Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
local E, COEF = 2.0e6, 1.0e12
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                             ALGO_CONT = 'PENALISATION', COEF_CONT = COEF,
                             CONTACT_INIT = 'NON' } }
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
  ['DEPL LAGS_C A'] = -9.999989997941e+04,
  ['DEPL DY A'] = -5.000004999962e-02,
  ['DEPL LAGS_C O'] = -9.999989998774e+04,
  ['DEPL DY O'] = -5.000004999918e-02,
  ['DEPL LAGS_C B'] = -9.999990001133e+04,
  ['DEPL DY B'] = -5.000005000046e-02,
  ['DEPL LAGS_C MIN(AB)'] = -9.999990002799e+04,
  ['DEPL DY MIN(AB)'] = -5.000005000467e-02,
  ['DEPL DY MIN(EF)'] = -4.999995000529e-02,
  ['SIGM_NOEU SIYY MIN(AB)'] = -9.999990001087e+04,
  ['SIGM_NOEU SIYY MIN(EF)'] = -9.999990003675e+04,
  ['DEPL LAGS_C MAX(AB)'] = -9.999989995652e+04,
  ['DEPL DY MAX(AB)'] = -5.000004999897e-02,
  ['DEPL DY MAX(EF)'] = -4.999994999904e-02,
  ['SIGM_NOEU SIYY MAX(AB)'] = -9.999989996938e+04,
  ['SIGM_NOEU SIYY MAX(EF)'] = -9.999989998808e+04,
}

local checks = {}
local function check(field, cmp, refe, where, kind, precision)
  local key = field .. ' ' .. cmp .. ' ' .. (kind and kind .. '(' .. where .. ')' or where)
  local test = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = field, NOM_CMP = cmp, VALE_CALC = assert(calc[key], key),
                   REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = precision or 1.0e-8 }
  if kind then test.GROUP_MA = where; test.TYPE_TEST = kind else test.GROUP_NO = where end
  checks[#checks + 1] = test
end
-- The exact penalised solution: the pressure p closes all but p/COEF of the 0.1 m imposed, two
-- blocks of unit height: 0.1 = 2 p / E + p / COEF.
local p = 0.1 * E / (2.0 + E / COEF)
local floor = 1.01 * E / (2.0 * COEF)                  -- the penalty floor E/(2 COEF), +1 %
local dy_slave, dy_master = -0.1 + p / E, -p / E             -- AB (upper block), EF (lower block)
for _, point in ipairs({ 'A', 'O', 'B' }) do
  check('DEPL', 'LAGS_C', -p, point)
  check('DEPL', 'LAGS_C', -1.0e5, point, nil, floor)
  check('DEPL', 'DY', dy_slave, point)
end
for _, kind in ipairs({ 'MIN', 'MAX' }) do
  check('DEPL', 'LAGS_C', -p, 'AB', kind)
  check('DEPL', 'LAGS_C', -1.0e5, 'AB', kind, floor)
  check('DEPL', 'DY', dy_slave, 'AB', kind)
  check('DEPL', 'DY', dy_master, 'EF', kind)
  for _, group in ipairs({ 'AB', 'EF' }) do
    check('SIGM_NOEU', 'SIYY', -p, group, kind)
  end
end
TEST_RESU{ RESU = checks }
FIN()
