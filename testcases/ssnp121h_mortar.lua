-- SSNP121 H with mortar contact: a linear slave (12 SEG2 on AB, QUAD4 upper block) on a quadratic
-- master (11 SEG3 on EF, QUAD8 lower block), non-matching.
-- Purpose: mortar contact (DEFI_CONT, APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN') between a
--          linear and a quadratic surface, CONTACT_INIT='INTERPENETRE' as in code_aster's model H.
-- Reference: analytical LAGS_C = SIYY = -1e5 Pa, DY = -0.05 m everywhere on AB and EF; every check
--            at 1e-8. Units SI. code_aster's CONTINUE method gets 0.17 % at A and B.
-- What we get: every value within 1.9e-14 (relative) of the analytical one.
-- Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121h.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'INTERPENETRE' } }
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
  ['DEPL DY A'] = -5.000000000000e-02,
  ['DEPL LAGS_C O'] = -1.000000000000e+05,
  ['DEPL DY O'] = -5.000000000000e-02,
  ['DEPL LAGS_C B'] = -1.000000000000e+05,
  ['DEPL DY B'] = -5.000000000000e-02,
  ['DEPL LAGS_C MIN(AB)'] = -1.000000000000e+05,
  ['DEPL DY MIN(AB)'] = -5.000000000000e-02,
  ['SIGM_NOEU SIYY MIN(AB)'] = -1.000000000000e+05,
  ['DEPL DY MIN(EF)'] = -5.000000000000e-02,
  ['SIGM_NOEU SIYY MIN(EF)'] = -1.000000000000e+05,
  ['DEPL LAGS_C MAX(AB)'] = -1.000000000000e+05,
  ['DEPL DY MAX(AB)'] = -5.000000000000e-02,
  ['SIGM_NOEU SIYY MAX(AB)'] = -1.000000000000e+05,
  ['DEPL DY MAX(EF)'] = -5.000000000000e-02,
  ['SIGM_NOEU SIYY MAX(EF)'] = -1.000000000000e+05,
}

local checks = require('lib.mortar_checks').new(RESU, calc)
checks.patch({ 'A', 'O', 'B' }, { 'A', 'O', 'B' }, 'AB', { 'AB', 'EF' }, 'DY', 'SIYY', -1.0e5, -0.05)
TEST_RESU{ RESU = checks.list }
FIN()
