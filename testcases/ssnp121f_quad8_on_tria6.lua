-- SSNP121 F with the roles swapped (seed remark): QUAD8 slave facing a TRIA6 master, a pairing that does
-- NOT satisfy the compatibility conditions for integrating the contact terms. Two unit cubes stacked:
-- V1 = [0,1]^3 (4x4x4 HEXA20, slave SURESC = QUAD8 face z=1), V2 = [0,1]^2 x [1,2] (4x4x4 PENTA15, master
-- SURMAI = TRIA6 face z=1), vertices matching. CONTINUE, default integration (AUTO: 3x3 Simpson on QUAD8),
-- COEF_CONT=1000. ENCAST clamped, SURCHA DX=DY=0, DZ=-0.1; E=2e6 Pa, NU=0.
-- Purpose: the run must warn (DEFI_CONTACT, once) and name the pairing to use instead (TRIA6 slave on the
-- quadrangle master = SSNP121 F, or the same cell type on both sides); tests/decks/warnings.cmake asserts it.
-- Result (non-regression only, VALE_CALC): every slave point sits on a master node and the slave weights
-- load the TRIA6 master's vertices, which a uniform pressure does not load, so the answer is wrong:
-- LAGS_C -1.0008e5 .. -1.1184e5 (errors up to 11.8 %), DZ -0.05028 / -0.05019 at A21..A24 (0.56 % / 0.39 %).
-- Both exceed code_aster's 0.1 % on every check, so no ANALYTIQUE check is made. REAC_GEOM='SANS' (pairing
-- in the flat initial geometry): with 'AUTOMATIQUE' the geometric fixed point does not converge (the
-- residual stalls near 0.37 after 10 re-pairings on the wavy, wrongly loaded master). Runtime label: fast.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE', REAC_GEOM = 'SANS',
                     ZONE = _F{ GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI', COEF_CONT = 1000.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }

local checks = {}
local function check(cmp, calc, group, kind)
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = cmp, GROUP_NO = group,
                            TYPE_TEST = kind, VALE_CALC = calc }
end
check('DZ', -5.028119917e-02, 'A21')
check('LAGS_C', -1.085532331e+05, 'A21')
check('DZ', -5.019322672e-02, 'A22')
check('LAGS_C', -1.068476290e+05, 'A22')
check('DZ', -5.028119917e-02, 'A23')
check('LAGS_C', -1.085532331e+05, 'A23')
check('DZ', -5.019322672e-02, 'A24')
check('LAGS_C', -1.068476290e+05, 'A24')
check('LAGS_C', -1.118422302e+05, 'SURESC', 'MIN')
check('LAGS_C', -1.000839012e+05, 'SURESC', 'MAX')
TEST_RESU{ RESU = checks }
FIN()
