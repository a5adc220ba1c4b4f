-- SSNP121 A with mortar contact and a thickness on each surface (DIST_ESCL, DIST_MAIT).
-- Purpose: DEFI_CONT's DIST_ESCL = 0.004 m and DIST_MAIT = 0.006 m keep the two surfaces 0.01 m apart
--          (shell-like thicknesses); the initial gap is then -0.01 m (interpenetrating:
--          CONTACT_INIT='INTERPENETRE' activates every slave node).
-- Reference: analytical. CD is pushed down by 0.1 m and the blocks end 0.01 m apart: the 2 m stack
--            now spans 1.9 m with 0.01 m of it empty, so each unit-height block is compressed by
--            0.055 m: strain -0.055, pressure E*strain = -1.1e5 Pa (LAGS_C and SIYY), DY = -0.045 m on
--            AB (upper block) and -0.055 m on EF. Units SI.
-- Runtime label: fast, contact, mortar.
-- lunaster: exact to round-off (errors below 1e-13).
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'INTERPENETRE',
                             DIST_ESCL = 0.004, DIST_MAIT = 0.006 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }

local checks = {}
local function check(field, group, cmp, refe, calc, kind)
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = field, GROUP_NO = group, NOM_CMP = cmp,
                            TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-8,
                            VALE_CALC = calc }
end
check('DEPL', 'O', 'LAGS_C', -1.1e5, -1.100000000000e+05)
check('DEPL', 'AB', 'LAGS_C', -1.1e5, -1.100000000000e+05, 'MIN')
check('DEPL', 'AB', 'LAGS_C', -1.1e5, -1.100000000000e+05, 'MAX')
check('DEPL', 'AB', 'DY', -0.045, -4.500000000000e-02, 'MIN')
check('DEPL', 'EF', 'DY', -0.055, -5.500000000000e-02, 'MAX')
check('SIGM_NOEU', 'AB', 'SIYY', -1.1e5, -1.100000000000e+05, 'MIN')
check('SIGM_NOEU', 'EF', 'SIYY', -1.1e5, -1.100000000000e+05, 'MAX')
TEST_RESU{ RESU = checks }
FIN()
