-- SSNP121 E with Simpson integration: the matching TRIA6/TRIA6 interface of testcases/ssnp121e.lua
-- (4x4x4 PENTA15 on 4x4x4 PENTA15, nodes facing each other) integrated with INTEGRATION='SIMPSON',
-- ORDRE_INT=2 and 4 instead of SSNP121 E's GAUSS, ORDRE_INT=4.
-- Purpose: Simpson on a triangle must be exact on each sub-triangle to degree 3, as on a segment
--          (vertices 1/40, mid-edges 1/15, centroid 9/40 of the sub-triangle area x 2). The
--          lattice weights without a centroid (vertices 1/30, mid-edges 4/30) are exact for linear
--          functions only: a uniform pressure no longer gives the consistent TRIA6 nodal forces and
--          LAGS_C came out 49 % (ORDRE_INT=2) and 16.5 % (ORDRE_INT=4) off.
-- Loading: ENCAST (z=0) clamped; SURCHA (z=2) DX=DY=0, DZ=-0.1. E=2e6 Pa, NU=0. COEF_CONT=1000.
-- Reference: analytical, uniform strain -0.05 in both blocks: LAGS_C = E*eps = -1e5 Pa on the whole
--            interface, DZ = -0.05 m on it (spec: SSNP121 D/E/F/K tolerance 0.1 %). Units SI.
--            Runtime label: fast, contact, 3D.
-- lunaster: largest relative error over all SURESC nodes 9.5e-13 (ORDRE_INT=2) and 4.1e-12 (ORDRE_INT=4)
--           on LAGS_C, 9.2e-13 on DZ (round-off).
--           Each value is checked at 1e-3 (code_aster's case) and at 1e-10 (the method is exact;
--           testcases/lib/ssnp121_3d_checks.lua).
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121e.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }

-- VALE_CALC per ORDRE_INT, recorded from runs: LAGS_C at A21..A24, min and max LAGS_C and DZ on SURESC.
local calc = {
  [2] = { A21 = -1.000000000000e+05, A22 = -1.000000000000e+05, A23 = -1.000000000000e+05,
          A24 = -9.999999999996e+04, MIN = -1.000000000001e+05, MAX = -9.999999999996e+04,
          DZMIN = -5.000000000002e-02, DZMAX = -4.999999999999e-02 },
  [4] = { A21 = -1.000000000002e+05, A22 = -9.999999999995e+04, A23 = -1.000000000000e+05,
          A24 = -1.000000000004e+05, MIN = -1.000000000004e+05, MAX = -9.999999999983e+04,
          DZMIN = -5.000000000005e-02, DZMAX = -4.999999999998e-02 },
}
local checks = {}
for _, ordre in ipairs({ 2, 4 }) do
  local cont = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                             ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                             ZONE = _F{ GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI', INTEGRATION = 'SIMPSON',
                                        ORDRE_INT = ordre, COEF_CONT = 1000.0 } }
  local resu = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = cont,
                              EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                              COMPORTEMENT = _F{ RELATION = 'ELAS' },
                              INCREMENT = _F{ LIST_INST = L_INST } }
  local check = require('lib.ssnp121_3d_checks')(checks, resu, 'SIMPSON ORDRE_INT=' .. ordre)
  local c = calc[ordre]
  for _, a in ipairs({ 'A21', 'A22', 'A23', 'A24' }) do check('LAGS_C', -1.0e5, c[a], a) end
  check('LAGS_C', -1.0e5, c.MIN, 'SURESC', 'MIN')
  check('LAGS_C', -1.0e5, c.MAX, 'SURESC', 'MAX')
  check('DZ', -0.05, c.DZMIN, 'SURESC', 'MIN')
  check('DZ', -0.05, c.DZMAX, 'SURESC', 'MAX')
end
TEST_RESU{ RESU = checks }
FIN()
