-- SSNP121 A: contact patch test of two elastic blocks pressed together (El-Abbasi & Bathe 2001).
-- Purpose: CONTINUE (augmented Lagrangian) contact between non-matching meshes: 12 SEG2 on the
--          slave edge AB (upper block) against 11 SEG2 on the master edge EF (lower block),
--          composite Simpson integration on 4 sub-elements (current code_aster: INTEGRATION='SIMPSON',
--          ORDRE_INT=4; the seed spelt it 'SIMPSON2'), COEF_CONT=1000, CONTACT_INIT='NON'.
-- Reference: analytical, uniform strain -0.05 in both blocks: LAGS_C = E*eps = -1e5 Pa everywhere on
--            AB, DY = U0/2 = -0.05 m on AB. Units SI. Runtime label: fast, contact.
-- code_aster gets LAGS_C -1.00080e5 at A, B (0.08 %) and -1.00351e5 at O (0.35 %); DY -0.049997 at
-- A, B and -0.049978 at O. The tolerances below are code_aster's (1 %).
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
                     ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                     REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON',
                                ORDRE_INT = 4, COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST },
                      CONVERGENCE = _F{ RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 } }
IMPR_RESU{ FORMAT = 'MED', RESU = _F{ RESULTAT = RESU } }

local checks = {}
for _, point in ipairs({ 'A', 'O', 'B' }) do
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'DY',
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.0e-2 }
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = 'LAGS_C',
                            REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 }
end
TEST_RESU{ RESU = checks }
FIN()
