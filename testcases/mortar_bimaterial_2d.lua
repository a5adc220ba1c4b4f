-- Mortar contact patch test, 2D, two materials: the SSNP121 A scene (upper block [-1,1]x[0,1],
-- 12x12 QUAD4, on lower block [-1,1]x[-1,0], 11x11 QUAD4; interface nodes do not face each other)
-- with unequal Young's moduli, E1 = 2e6 Pa above, E2 = 6e6 Pa below (Poisson 0).
-- Purpose: mortar contact (DEFI_CONT, APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN', slave AB on master
--          EF, CONTACT_INIT='INTERPENETRE') across a material jump: the interface displacement is no
--          longer half the imposed one, so a pressure or a gap computed with the wrong side's
--          stiffness, or a non-uniform transfer between the meshes, shows.
-- Reference: analytical. CD: DY = -0.1, GH fixed: the blocks are springs in series,
--            p = 0.1 / (1/E1 + 1/E2) = 1.5e5 Pa, LAGS_C = SIYY = -p on AB and EF, DY = -p/E2 =
--            -0.025 m on both sides of the interface; every check at 1e-8. Units SI.
-- What we get: every value within 1.0e-14 (relative) of the analytical one.
-- Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
local E1, E2 = 2.0e6, 6.0e6                                  -- upper, lower block (Pa)
MAT1 = DEFI_MATERIAU{ ELAS = _F{ E = E1, NU = 0.0 } }
MAT2 = DEFI_MATERIAU{ ELAS = _F{ E = E2, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'PLAQUE1', MATER = MAT1 },
                                               _F{ GROUP_MA = 'PLAQUE2', MATER = MAT2 } } }
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
  ['DEPL LAGS_C A'] = -1.500000000000e+05,
  ['DEPL DY A'] = -2.500000000000e-02,
  ['DEPL LAGS_C O'] = -1.500000000000e+05,
  ['DEPL DY O'] = -2.500000000000e-02,
  ['DEPL LAGS_C B'] = -1.500000000000e+05,
  ['DEPL DY B'] = -2.500000000000e-02,
  ['DEPL DY E'] = -2.500000000000e-02,
  ['DEPL DY F'] = -2.500000000000e-02,
  ['DEPL LAGS_C MIN(AB)'] = -1.500000000000e+05,
  ['DEPL DY MIN(AB)'] = -2.500000000000e-02,
  ['SIGM_NOEU SIYY MIN(AB)'] = -1.500000000000e+05,
  ['DEPL DY MIN(EF)'] = -2.500000000000e-02,
  ['SIGM_NOEU SIYY MIN(EF)'] = -1.500000000000e+05,
  ['DEPL LAGS_C MAX(AB)'] = -1.500000000000e+05,
  ['DEPL DY MAX(AB)'] = -2.500000000000e-02,
  ['SIGM_NOEU SIYY MAX(AB)'] = -1.500000000000e+05,
  ['DEPL DY MAX(EF)'] = -2.500000000000e-02,
  ['SIGM_NOEU SIYY MAX(EF)'] = -1.500000000000e+05,
}

-- Two springs in series: 0.1 = p / E1 + p / E2 (blocks of unit height).
local p = 0.1 / (1.0 / E1 + 1.0 / E2)
local dy = -p / E2                                          -- the interface, on both sides
local checks = require('lib.mortar_checks').new(RESU, calc)
checks.patch({ 'A', 'O', 'B' }, { 'A', 'O', 'B', 'E', 'F' }, 'AB', { 'AB', 'EF' }, 'DY', 'SIYY', -p, dy)
TEST_RESU{ RESU = checks.list }
FIN()
