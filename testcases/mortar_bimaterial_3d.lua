-- Mortar contact patch test, 3D, two materials, non-matching cell types and sizes: V1 = [0,1]^3 (lower,
-- 5x5x2 PENTA6, slave SURESC: 50 TRIA3, legs 0.2) under V2 = [0,1]^2 x [1,2] (upper, 3x3x2 HEXA20,
-- master SURMAI: 9 QUAD8 of side 1/3): no interior slave edge lies on a master edge, each slave triangle is
-- clipped by up to four master quadrangles. Young's moduli E1 = 6e6 Pa (V1), E2 = 2e6 Pa (V2), NU = 0.
-- Purpose: mortar contact (DEFI_CONT, APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN', CONTACT_INIT='NON')
--          across a material jump, where the interface displacement is not half the imposed one.
-- Loading: ENCAST (z=0) clamped; SURCHA (z=2) DX=DY=0, DZ=-0.1.
-- Reference: analytical, springs in series: p = 0.1 / (1/E1 + 1/E2) = 1.5e5 Pa, LAGS_C = SIZZ = -p on
--            the whole interface (both sides), DZ = -p/E1 = -0.025 m on it; every check at 1e-8.
--            Units SI.
-- What we get: every value within 3.2e-13 (relative) of the analytical one.
-- Runtime label: fast, contact, 3D.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/nonmatching3d_penta6_hexa20.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
local E1, E2 = 6.0e6, 2.0e6                                  -- lower (V1), upper (V2) block (Pa)
MAT1 = DEFI_MATERIAU{ ELAS = _F{ E = E1, NU = 0.0 } }
MAT2 = DEFI_MATERIAU{ ELAS = _F{ E = E2, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'V1', MATER = MAT1 }, _F{ GROUP_MA = 'V2', MATER = MAT2 } } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
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
  ['DEPL LAGS_C A21'] = -1.500000000000e+05,
  ['DEPL DZ A21'] = -2.500000000000e-02,
  ['DEPL LAGS_C A22'] = -1.500000000000e+05,
  ['DEPL DZ A22'] = -2.500000000000e-02,
  ['DEPL LAGS_C A23'] = -1.500000000000e+05,
  ['DEPL DZ A23'] = -2.500000000000e-02,
  ['DEPL LAGS_C A24'] = -1.500000000000e+05,
  ['DEPL DZ A24'] = -2.500000000000e-02,
  ['DEPL LAGS_C MIN(SURESC)'] = -1.500000000000e+05,
  ['DEPL DZ MIN(SURESC)'] = -2.500000000000e-02,
  ['SIGM_NOEU SIZZ MIN(SURESC)'] = -1.500000000000e+05,
  ['DEPL DZ MIN(SURMAI)'] = -2.500000000000e-02,
  ['SIGM_NOEU SIZZ MIN(SURMAI)'] = -1.500000000000e+05,
  ['DEPL LAGS_C MAX(SURESC)'] = -1.500000000000e+05,
  ['DEPL DZ MAX(SURESC)'] = -2.500000000000e-02,
  ['SIGM_NOEU SIZZ MAX(SURESC)'] = -1.500000000000e+05,
  ['DEPL DZ MAX(SURMAI)'] = -2.500000000000e-02,
  ['SIGM_NOEU SIZZ MAX(SURMAI)'] = -1.500000000000e+05,
}

-- Two springs in series: 0.1 = p / E1 + p / E2 (blocks of unit height).
local p = 0.1 / (1.0 / E1 + 1.0 / E2)
local dz = -p / E1                                          -- the interface, on both sides
local checks = require('lib.mortar_checks').new(RESU, calc)
checks.patch({ 'A21', 'A22', 'A23', 'A24' }, { 'A21', 'A22', 'A23', 'A24' }, 'SURESC', { 'SURESC', 'SURMAI' }, 'DZ', 'SIZZ',
             -p, dz)
TEST_RESU{ RESU = checks.list }
FIN()
