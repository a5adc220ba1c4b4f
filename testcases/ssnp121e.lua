-- SSNP121 E: 3D contact patch test, two unit cubes stacked (V1 = [0,1]^3 below, V2 = [0,1]^2 x [1,2]
-- above), each meshed with 4x4x4 PENTA15 (every xy square split in two triangles), interface nodes
-- duplicated but facing each other (matching).
-- Purpose: CONTINUE contact TRIA6 slave (SURESC, z=1 face of V1) on TRIA6 master (SURMAI, z=1 face of
--          V2); Gauss integration with ORDRE_INT=4 (6 points per triangle), COEF_CONT=1000.
-- Loading: ENCAST (z=0) clamped; SURCHA (z=2) DX=DY=0, DZ=-0.1. E=2e6 Pa, NU=0.
-- Reference: analytical, uniform strain -0.05 in both blocks: LAGS_C = E*eps = -1e5 Pa on the whole
--            interface, DZ = -0.05 m on it. Units SI. Runtime label: fast, contact, 3D.
-- code_aster: error < 0.02 % at A21..A24 and on min/max LAGS_C over SURESC; tolerance 0.1 %.
-- lunaster: largest relative error over all SURESC nodes 4.0e-13 on LAGS_C, 1.1e-14 on DZ (round-off).
--           Each value is checked at 1e-3 (code_aster's case) and at 1e-10 (the method is exact;
--           testcases/lib/ssnp121_3d_checks.lua).
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                     ZONE = _F{ GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI', INTEGRATION = 'GAUSS', ORDRE_INT = 4,
                                COEF_CONT = 1000.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }

local checks = {}
local check = require('lib.ssnp121_3d_checks')(checks, RESU)
check('DZ', -0.05, -5.000000000000e-02, 'A21')
check('LAGS_C', -1.0e5, -1.000000000000e+05, 'A21')
check('DZ', -0.05, -5.000000000000e-02, 'A22')
check('LAGS_C', -1.0e5, -9.999999999998e+04, 'A22')
check('DZ', -0.05, -5.000000000000e-02, 'A23')
check('LAGS_C', -1.0e5, -9.999999999997e+04, 'A23')
check('DZ', -0.05, -5.000000000000e-02, 'A24')
check('LAGS_C', -1.0e5, -1.000000000000e+05, 'A24')
check('LAGS_C', -1.0e5, -1.000000000000e+05, 'SURESC', 'MIN')
check('LAGS_C', -1.0e5, -9.999999999996e+04, 'SURESC', 'MAX')
TEST_RESU{ RESU = checks }
FIN()
