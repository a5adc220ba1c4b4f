-- SSNP121 G: model A loaded by a pressure instead of an imposed displacement.
-- A pressure P0 = E*eps = 1e5 Pa on CD (PRES_REP, after ORIE_PEAU_2D so that the normal of CD points
-- out of the upper block) is equivalent to U0 = -0.1. GH is fixed and DX = 0 at the node D only.
-- Without initial contact the upper block would be a rigid body at the first iteration: the seed
-- requires CONTACT_INIT='OUI' (see ssnp121g_noinit.lua in testcases/errors for what happens otherwise).
-- CONTINUE, Simpson on 4 sub-elements, COEF_CONT 1000; seed syntax (AFFE_CHAR_MECA/CONTACT).
-- Reference: analytical LAGS_C = -1e5 Pa, DY = -0.05 m on AB; code_aster's values are those of model A.
-- Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
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
                                     CONTACT_INIT = 'OUI', ITER_GEOM_MAXI = 10, ITER_CONT_MAXI = 30 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT,
                      EXCIT = { _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, _F{ CHARGE = CHA2 } },
                      COMP_ELAS = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6).
local calc = {
  A = { DY = -4.999669852730e-02, LAGS_C = -1.000793897087e+05 },
  O = { DY = -4.997834591412e-02, LAGS_C = -1.003594760083e+05 },
  B = { DY = -4.999668381794e-02, LAGS_C = -1.000794354964e+05 },
}
local checks = {}
for _, point in ipairs({ 'A', 'O', 'B' }) do
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'DY', VALE_CALC = calc[point].DY,
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.0e-2 }
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'LAGS_C', VALE_CALC = calc[point].LAGS_C,
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 }
end
TEST_RESU{ RESU = checks }
FIN()
