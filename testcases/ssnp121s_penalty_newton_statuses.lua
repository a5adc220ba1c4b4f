-- SSNP121 S-like: the upper block pressed by a pressure onto the lower one, held vertically by the
-- contact alone (its only support is DX = 0 at its corner C), with penalised CONTINUE contact whose
-- statuses are updated inside Newton (ALGO_RESO_CONT = 'NEWTON') and CONTACT_INIT = 'INTERPENETRE'
-- on blocks that touch with zero gap. The statuses CONTACT_INIT sets must carry the first Newton
-- iteration: judged again on the start (zero gap, zero pressure) they all opened, and the upper block
-- was held by nothing. code_aster's SSNP121S (COEF_PENA_CONT = 1e16) tests the same.
-- Reference: analytical, uniform stress -1e5 Pa in both blocks: LAGS_C = -1e5 Pa on AB, DY = -0.05 m
-- on AB (the penetration p / COEF_PENA_CONT = 1e-7 m is below the 1 % tolerance), SIEF_NOEU SIYY = -1e5
-- Pa at the corners and on the interface. Units SI.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'CD' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
FIXED = AFFE_CHAR_MECA{ MODELE = MO,
                        DDL_IMPO = { _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 }, _F{ GROUP_NO = 'C', DX = 0.0 } } }
PRESSED = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'CD', PRES = 1.0e5 } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'NEWTON', ALGO_RESO_GEOM = 'NEWTON',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
                                CONTACT_INIT = 'INTERPENETRE', ALGO_CONT = 'PENALISATION',
                                COEF_PENA_CONT = 1.0e12 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = { _F{ CHARGE = FIXED }, _F{ CHARGE = PRESSED } },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST },
                      CONVERGENCE = _F{ ITER_GLOB_MAXI = 40 } }
-- The stresses of the behaviour at the cells' nodes and their nodal means (with ELAS, SIGM's).
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = { 'SIEF_ELNO', 'SIEF_NOEU' } }
-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6).
local calc = {
  A = { DY = -5.000010379e-02, LAGS_C = -1.000001277e+05 },
  O = { DY = -5.000009321e-02, LAGS_C = -1.000000625e+05 },
  B = { DY = -5.000010379e-02, LAGS_C = -1.000001277e+05 },
}
local checks = {}
for _, point in ipairs({ 'A', 'O', 'B' }) do
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'DY', VALE_CALC = calc[point].DY,
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.0e-2 }
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'LAGS_C', VALE_CALC = calc[point].LAGS_C,
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 }
end
local siyy = { A = -1.000000766e+05, O = -1.000000476e+05, B = -1.000000766e+05, C = -1.000000000e+05,
               H = -1.000000050e+05 }
for _, point in ipairs({ 'A', 'O', 'B', 'C', 'H' }) do  -- uniform -1e5 Pa through both blocks
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'SIEF_NOEU', GROUP_NO = point, NOM_CMP = 'SIYY',
                            VALE_CALC = siyy[point],
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-3 }
end
TEST_RESU{ RESU = checks }
FIN()
