-- Mortar contact with two zones, 2D: three blocks stacked and meshed apart, so two non-matching
-- interfaces. PLAQUE2 = [-1,1]x[-1,0] (bottom, 11x11 QUAD4), PLAQUE1 = [-1,1]x[0,1] (middle, 12x12
-- QUAD4), PLAQUE3 = [-1,1]x[1,2] (top, 5x5 squares cut into 50 TRIA6). Zone 1: slave AB (middle
-- block, SEG2) on master EF (bottom block, SEG2). Zone 2: slave IJ (top block, SEG3) on master CD
-- (middle block, SEG2). The middle block is slave in one zone and master in the other.
-- Young's moduli E2 = 6e6 Pa (bottom), E1 = 2e6 Pa (middle), E3 = 3e6 Pa (top), Poisson 0.
-- Purpose: DEFI_CONT with ZONE given twice (APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN',
--          CONTACT_INIT='OUI', as the middle block
--          is held by contact alone in DY): each zone pairs, integrates and condenses on its own interface, and
--          both carry the same pressure, which neither would if a zone's rows, multipliers or
--          condensation leaked into the other's.
-- Loading: GH fixed; KL DX = 0, DY = -0.1; CD DX = 0 (the middle block's rigid sliding; DX = 0
--          everywhere in the exact solution, and it is tangential to the interface).
-- Reference: analytical, three springs in series: p = 0.1 / (1/E1 + 1/E2 + 1/E3) = 1e5 Pa,
--            LAGS_C = SIYY = -p on both interfaces (both sides); DY = -p/E2 = -1/60 m on y = 0 and
--            -p/E2 - p/E1 = -1/15 m on y = 1; every check at 1e-8. Units SI.
-- What we get: every value within 3.0e-14 (relative) of the analytical one.
-- Mesh: lunaster-meshgen --upper quad4:12 --lower quad4:11 --top tria6:5 -o meshes/mortar_two_zones_2d.med
-- Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/mortar_two_zones_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
local E1, E2, E3 = 2.0e6, 6.0e6, 3.0e6                       -- middle, bottom, top block (Pa)
MAT1 = DEFI_MATERIAU{ ELAS = _F{ E = E1, NU = 0.0 } }
MAT2 = DEFI_MATERIAU{ ELAS = _F{ E = E2, NU = 0.0 } }
MAT3 = DEFI_MATERIAU{ ELAS = _F{ E = E3, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'PLAQUE1', MATER = MAT1 },
                                               _F{ GROUP_MA = 'PLAQUE2', MATER = MAT2 },
                                               _F{ GROUP_MA = 'PLAQUE3', MATER = MAT3 } } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'KL', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'CD', DX = 0.0 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = { _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                               ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'OUI' },
                           _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'IJ', GROUP_MA_MAIT = 'CD',
                               ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'OUI' } } }
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
  ['DEPL LAGS_C O'] = -1.000000000000e+05,
  ['DEPL LAGS_C B'] = -1.000000000000e+05,
  ['DEPL DY A'] = -1.666666666667e-02,
  ['DEPL DY O'] = -1.666666666667e-02,
  ['DEPL DY B'] = -1.666666666667e-02,
  ['DEPL DY E'] = -1.666666666667e-02,
  ['DEPL DY F'] = -1.666666666667e-02,
  ['DEPL LAGS_C MIN(AB)'] = -1.000000000000e+05,
  ['DEPL DY MIN(AB)'] = -1.666666666667e-02,
  ['SIGM_NOEU SIYY MIN(AB)'] = -1.000000000000e+05,
  ['DEPL DY MIN(EF)'] = -1.666666666667e-02,
  ['SIGM_NOEU SIYY MIN(EF)'] = -1.000000000000e+05,
  ['DEPL LAGS_C MAX(AB)'] = -1.000000000000e+05,
  ['DEPL DY MAX(AB)'] = -1.666666666667e-02,
  ['SIGM_NOEU SIYY MAX(AB)'] = -1.000000000000e+05,
  ['DEPL DY MAX(EF)'] = -1.666666666667e-02,
  ['SIGM_NOEU SIYY MAX(EF)'] = -1.000000000000e+05,
  ['DEPL LAGS_C I'] = -1.000000000000e+05,
  ['DEPL LAGS_C P'] = -1.000000000000e+05,
  ['DEPL LAGS_C J'] = -1.000000000000e+05,
  ['DEPL DY I'] = -6.666666666667e-02,
  ['DEPL DY P'] = -6.666666666667e-02,
  ['DEPL DY J'] = -6.666666666667e-02,
  ['DEPL DY C'] = -6.666666666667e-02,
  ['DEPL DY D'] = -6.666666666667e-02,
  ['DEPL LAGS_C MIN(IJ)'] = -1.000000000000e+05,
  ['DEPL DY MIN(IJ)'] = -6.666666666667e-02,
  ['SIGM_NOEU SIYY MIN(IJ)'] = -1.000000000000e+05,
  ['DEPL DY MIN(CD)'] = -6.666666666667e-02,
  ['SIGM_NOEU SIYY MIN(CD)'] = -1.000000000000e+05,
  ['DEPL LAGS_C MAX(IJ)'] = -1.000000000000e+05,
  ['DEPL DY MAX(IJ)'] = -6.666666666667e-02,
  ['SIGM_NOEU SIYY MAX(IJ)'] = -1.000000000000e+05,
  ['DEPL DY MAX(CD)'] = -6.666666666667e-02,
  ['SIGM_NOEU SIYY MAX(CD)'] = -1.000000000000e+05,
}

-- Three springs in series: 0.1 = p / E1 + p / E2 + p / E3 (blocks of unit height).
local p = 0.1 / (1.0 / E1 + 1.0 / E2 + 1.0 / E3)
local dy0 = -p / E2                                          -- y = 0, both sides
local dy1 = dy0 - p / E1                                     -- y = 1, both sides
local checks = require('lib.mortar_checks').new(RESU, calc)
checks.patch({ 'A', 'O', 'B' }, { 'A', 'O', 'B', 'E', 'F' }, 'AB', { 'AB', 'EF' }, 'DY', 'SIYY', -p, dy0)
checks.patch({ 'I', 'P', 'J' }, { 'I', 'P', 'J', 'C', 'D' }, 'IJ', { 'IJ', 'CD' }, 'DY', 'SIYY', -p, dy1)
TEST_RESU{ RESU = checks.list }
FIN()
