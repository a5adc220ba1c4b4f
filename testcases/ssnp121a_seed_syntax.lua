-- SSNP121 A written in the seed's syntax: contact as a charge, AFFE_CHAR_MECA{CONTACT=_F{METHODE=...}},
-- passed in EXCIT, with COMP_ELAS. Both syntaxes of docs/deck-syntax.md must mean the same thing: this
-- deck checks the very VALE_CALC values of ssnp121a.lua (which uses DEFI_CONTACT + COMPORTEMENT).
-- The seed's INTEGRATION='SIMPSON2' means three sub-elements; code_aster's current deck (whose numbers
-- ssnp121a.lua is compared with) uses SIMPSON with ORDRE_INT=4, spelt here as in the seed's catalogue.
-- Reference: analytical LAGS_C = -1e5 Pa, DY = -0.05 m. Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CHA2 = AFFE_CHAR_MECA{ MODELE = MO,
                       CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                                     INTEGRATION = 'SIMPSON', ORDRE_INT = 4, COEF_REGU_CONT = 1000.0,
                                     CONTACT_INIT = 'NON', ALGO_RESO_CONT = 'POINT_FIXE',
                                     ALGO_RESO_GEOM = 'POINT_FIXE', REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT,
                      EXCIT = { _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, _F{ CHARGE = CHA2 } },
                      COMP_ELAS = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST },
                      CONVERGENCE = _F{ RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6).
local calc = {
  A = { DY = -4.999669690478e-02, LAGS_C = -1.000795227287e+05 },
  O = { DY = -4.997830886910e-02, LAGS_C = -1.003593668221e+05 },
  B = { DY = -4.999669690478e-02, LAGS_C = -1.000795227287e+05 },
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
