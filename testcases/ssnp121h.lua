-- SSNP121 H: CONTINUE contact between a linear slave (12 SEG2 on AB, QUAD4 upper block) and a
-- quadratic master (11 SEG3 on EF, QUAD8 lower block), non-matching. Newton-Cotes integration of
-- degree 8 (seed: 'NCOTES2'; current code_aster: INTEGRATION='NCOTES', ORDRE_INT=8), CONTACT_INIT
-- 'INTERPENETRE'. Reference: analytical LAGS_C = -1e5 Pa, DY = -0.05 m at A and B.
-- code_aster: LAGS_C -1.00173e5 (0.17 %), DY -0.049971 (0.06 %) at A and B; tolerance 0.5 %.
-- Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'NCOTES',
                                ORDRE_INT = 8, COEF_CONT = 100.0, CONTACT_INIT = 'INTERPENETRE' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6).
local calc = {
  A = { DY = -4.997066778877e-02, LAGS_C = -1.001716111979e+05 },
  B = { DY = -4.997066778877e-02, LAGS_C = -1.001716111979e+05 },
}
local checks = {}
for _, point in ipairs({ 'A', 'B' }) do
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'DY', VALE_CALC = calc[point].DY,
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 5.0e-3 }
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'LAGS_C', VALE_CALC = calc[point].LAGS_C,
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 5.0e-3 }
end
TEST_RESU{ RESU = checks }
FIN()
