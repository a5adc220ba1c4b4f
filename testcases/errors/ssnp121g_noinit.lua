-- Model G of SSNP121 with CONTACT_INIT='NON': the upper block is held only by contact, which is not
-- active at the first iteration, so the stiffness is singular. The run must stop with a clear message
-- naming the body and the direction and the remedy (CONTACT_INIT='OUI'), never with garbage or a crash.
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: ssnp121g_noinit\.lua:[0-9]+: STAT_NON_LINE: .*singular
-- EXPECT_ERROR: PLAQUE1
-- EXPECT_ERROR: rigid-body mode
-- EXPECT_ERROR: CONTACT_INIT='OUI'
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'CD' } }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'D', DX = 0.0 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } },
                       PRES_REP = _F{ GROUP_MA = 'CD', PRES = 1.0e5 } }
CHA2 = AFFE_CHAR_MECA{ MODELE = MO,
                       CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                                     INTEGRATION = 'SIMPSON', ORDRE_INT = 4, COEF_REGU_CONT = 1000.0,
                                     CONTACT_INIT = 'NON', ITER_GEOM_MAXI = 10, ITER_CONT_MAXI = 30 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT,
                      EXCIT = { _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, _F{ CHARGE = CHA2 } },
                      COMP_ELAS = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }

local checks = {}
for _, point in ipairs({ 'A', 'O', 'B' }) do
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'DY',
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.0e-2 }
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'LAGS_C',
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 }
end
TEST_RESU{ RESU = checks }
FIN()
