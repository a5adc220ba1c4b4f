-- SSNP121 A with mortar contact: the contact patch test of two elastic blocks pressed together
-- (El-Abbasi & Bathe 2001) on the non-matching mesh of model A.
-- Purpose: mortar contact (DEFI_CONT, APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN'): dual multipliers,
--          one weighted-gap condition per slave node; slave AB (12 SEG2, upper block) against master
--          EF (11 SEG2, lower block), CONTACT_INIT='NON'.
-- Reference: analytical, uniform strain -0.05 in both blocks: LAGS_C = SIYY = E*eps = -1e5 Pa
--            everywhere on AB and EF, DY = U0/2 = -0.05 m on AB and EF. Units SI.
-- Mortar passes the patch test on non-matching meshes to round-off: every check is at 1e-8
-- (code_aster's CONTINUE method gets 0.35 % at O, model A).
-- What we get: every value within 1.2e-14 (relative) of the analytical one.
-- Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
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
-- The result in MED: every step with the same DEPL components (LAGS_C at NUME_ORDRE 0 too).
IMPR_RESU{ FORMAT = 'MED', RESU = _F{ RESULTAT = RESU } }

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
