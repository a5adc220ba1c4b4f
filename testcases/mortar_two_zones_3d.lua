-- Mortar contact with two zones, 3D: three blocks stacked and meshed apart, so two non-matching
-- interfaces of different cell types. V1 = [0,1]^3 (bottom, 5x5x2 HEXA8), V2 = [0,1]^2 x [1,2]
-- (middle, 3x3x2 HEXA20), V3 = [0,1]^2 x [2,3] (top, 4x4x2 squares cut into 64 PENTA6). Zone 1:
-- slave SURESC (V1 z=1, 25 QUAD4) on master SURMAI (V2 z=1, 9 QUAD8). Zone 2: slave SURBA3 (V3 z=2,
-- 32 TRIA3) on master SURCHA (V2 z=2, 9 QUAD8). The middle block is master in both zones.
-- Young's moduli E1 = 6e6 Pa (V1), E2 = 2e6 Pa (V2), E3 = 3e6 Pa (V3), Poisson 0.
-- Purpose: DEFI_CONT with ZONE given twice (APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN',
--          CONTACT_INIT='OUI', as the middle block is held by contact alone in DZ): each zone pairs,
--          clips, integrates and condenses on its own interface, and both carry the same pressure.
-- Loading: ENCAST (z=0) clamped; SURCH3 (z=3) DX=DY=0, DZ=-0.1; SURCHA DX=DY=0 (the middle block's
--          rigid sliding; DX = DY = 0 everywhere in the exact solution, tangential to the interface).
-- Reference: analytical, three springs in series: p = 0.1 / (1/E1 + 1/E2 + 1/E3) = 1e5 Pa,
--            LAGS_C = SIZZ = -p on both interfaces (both sides); DZ = -p/E1 = -1/60 m on z = 1 and
--            -p/E1 - p/E2 = -1/15 m on z = 2; every check at 1e-8. Units SI.
-- What we get: every value within 3.5e-13 (relative) of the analytical one.
-- Mesh: lunaster-meshgen --v1 hexa8:5x5x2 --v2 hexa20:3x3x2 --v3 penta6:4x4x2 -o meshes/mortar_two_zones_3d.med
-- Runtime label: fast, contact, 3D.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/mortar_two_zones_3d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
local E1, E2, E3 = 6.0e6, 2.0e6, 3.0e6                       -- bottom, middle, top block (Pa)
MAT1 = DEFI_MATERIAU{ ELAS = _F{ E = E1, NU = 0.0 } }
MAT2 = DEFI_MATERIAU{ ELAS = _F{ E = E2, NU = 0.0 } }
MAT3 = DEFI_MATERIAU{ ELAS = _F{ E = E3, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'V1', MATER = MAT1 }, _F{ GROUP_MA = 'V2', MATER = MAT2 },
                                               _F{ GROUP_MA = 'V3', MATER = MAT3 } } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0 },
                                    _F{ GROUP_NO = 'SURCH3', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = { _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI',
                               ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'OUI' },
                           _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURBA3', GROUP_MA_MAIT = 'SURCHA',
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
  ['DEPL LAGS_C A21'] = -1.000000000000e+05,
  ['DEPL LAGS_C A22'] = -1.000000000000e+05,
  ['DEPL LAGS_C A23'] = -1.000000000000e+05,
  ['DEPL LAGS_C A24'] = -1.000000000000e+05,
  ['DEPL DZ A21'] = -1.666666666667e-02,
  ['DEPL DZ A23'] = -1.666666666667e-02,
  ['DEPL LAGS_C MIN(SURESC)'] = -1.000000000000e+05,
  ['DEPL DZ MIN(SURESC)'] = -1.666666666667e-02,
  ['SIGM_NOEU SIZZ MIN(SURESC)'] = -1.000000000000e+05,
  ['DEPL DZ MIN(SURMAI)'] = -1.666666666667e-02,
  ['SIGM_NOEU SIZZ MIN(SURMAI)'] = -1.000000000000e+05,
  ['DEPL LAGS_C MAX(SURESC)'] = -9.999999999999e+04,
  ['DEPL DZ MAX(SURESC)'] = -1.666666666667e-02,
  ['SIGM_NOEU SIZZ MAX(SURESC)'] = -9.999999999999e+04,
  ['DEPL DZ MAX(SURMAI)'] = -1.666666666667e-02,
  ['SIGM_NOEU SIZZ MAX(SURMAI)'] = -1.000000000000e+05,
  ['DEPL LAGS_C A31'] = -1.000000000000e+05,
  ['DEPL LAGS_C A32'] = -1.000000000000e+05,
  ['DEPL LAGS_C A33'] = -1.000000000000e+05,
  ['DEPL LAGS_C A34'] = -9.999999999998e+04,
  ['DEPL DZ A31'] = -6.666666666667e-02,
  ['DEPL DZ A33'] = -6.666666666667e-02,
  ['DEPL LAGS_C MIN(SURBA3)'] = -1.000000000000e+05,
  ['DEPL DZ MIN(SURBA3)'] = -6.666666666667e-02,
  ['SIGM_NOEU SIZZ MIN(SURBA3)'] = -1.000000000000e+05,
  ['DEPL DZ MIN(SURCHA)'] = -6.666666666667e-02,
  ['SIGM_NOEU SIZZ MIN(SURCHA)'] = -1.000000000000e+05,
  ['DEPL LAGS_C MAX(SURBA3)'] = -9.999999999997e+04,
  ['DEPL DZ MAX(SURBA3)'] = -6.666666666667e-02,
  ['SIGM_NOEU SIZZ MAX(SURBA3)'] = -9.999999999999e+04,
  ['DEPL DZ MAX(SURCHA)'] = -6.666666666666e-02,
  ['SIGM_NOEU SIZZ MAX(SURCHA)'] = -9.999999999999e+04,
}

-- Three springs in series: 0.1 = p / E1 + p / E2 + p / E3 (blocks of unit height).
local p = 0.1 / (1.0 / E1 + 1.0 / E2 + 1.0 / E3)
local dz1 = -p / E1                                          -- z = 1, both sides
local dz2 = dz1 - p / E2                                     -- z = 2, both sides
local checks = require('lib.mortar_checks').new(RESU, calc)
checks.patch({ 'A21', 'A22', 'A23', 'A24' }, { 'A21', 'A23' }, 'SURESC', { 'SURESC', 'SURMAI' }, 'DZ', 'SIZZ', -p, dz1)
checks.patch({ 'A31', 'A32', 'A33', 'A34' }, { 'A31', 'A33' }, 'SURBA3', { 'SURBA3', 'SURCHA' }, 'DZ', 'SIZZ', -p, dz2)
TEST_RESU{ RESU = checks.list }
FIN()
