-- SSNP121 D with mortar contact: 3D contact patch test, two unit cubes stacked (V1 = [0,1]^3 below,
-- V2 = [0,1]^2 x [1,2] above), each meshed with 4x4x4 HEXA20: QUAD8 slave (SURESC, z=1 face of V1) on
-- QUAD8 master (SURMAI, z=1 face of V2), nodes facing each other.
-- Purpose: mortar contact (DEFI_CONT, APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN',
--          CONTACT_INIT='INTERPENETRE') on a quadratic quadrangle slave: dual basis of the transformed
--          QUAD8 shape functions. code_aster's CONTINUE method gets < 0.02 %.
-- Loading: ENCAST (z=0) clamped; SURCHA (z=2) DX=DY=0, DZ=-0.1. E=2e6 Pa, NU=0.
-- Reference: analytical, uniform strain -0.05 in both blocks: LAGS_C = SIZZ = E*eps = -1e5 Pa on the
--            whole interface (both sides), DZ = -0.05 m on it; every check at 1e-8. Units SI.
-- What we get: every value within 4.2e-13 (relative) of the analytical one.
-- Runtime label: fast, contact, 3D.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'INTERPENETRE' } }
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
  ['DEPL LAGS_C A21'] = -1.000000000000e+05,
  ['DEPL DZ A21'] = -5.000000000000e-02,
  ['DEPL LAGS_C A22'] = -9.999999999999e+04,
  ['DEPL DZ A22'] = -5.000000000000e-02,
  ['DEPL LAGS_C A23'] = -1.000000000000e+05,
  ['DEPL DZ A23'] = -5.000000000000e-02,
  ['DEPL LAGS_C A24'] = -1.000000000000e+05,
  ['DEPL DZ A24'] = -5.000000000000e-02,
  ['DEPL LAGS_C MIN(SURESC)'] = -1.000000000000e+05,
  ['DEPL DZ MIN(SURESC)'] = -5.000000000000e-02,
  ['SIGM_NOEU SIZZ MIN(SURESC)'] = -1.000000000000e+05,
  ['DEPL DZ MIN(SURMAI)'] = -5.000000000000e-02,
  ['SIGM_NOEU SIZZ MIN(SURMAI)'] = -1.000000000000e+05,
  ['DEPL LAGS_C MAX(SURESC)'] = -9.999999999996e+04,
  ['DEPL DZ MAX(SURESC)'] = -5.000000000000e-02,
  ['SIGM_NOEU SIZZ MAX(SURESC)'] = -9.999999999999e+04,
  ['DEPL DZ MAX(SURMAI)'] = -5.000000000000e-02,
  ['SIGM_NOEU SIZZ MAX(SURMAI)'] = -9.999999999999e+04,
}

local checks = require('lib.mortar_checks').new(RESU, calc)
checks.patch({ 'A21', 'A22', 'A23', 'A24' }, { 'A21', 'A22', 'A23', 'A24' }, 'SURESC', { 'SURESC', 'SURMAI' }, 'DZ', 'SIZZ', -1.0e5, -0.05)
TEST_RESU{ RESU = checks.list }
FIN()
