-- Must-fail deck: ALGO_CONT='PENALISATION' in DEFI_CONT has no default penalty (COEF_CONT, Pa/m, is
-- required there: a default would depend on the unit system).
-- EXPECT_ERROR: mortar_penalty_without_coef\.lua:14: DEFI_CONT: ZONE\[1\]\.COEF_CONT: expected real > 0 \(mandatory keyword\), got nothing
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', ALGO_CONT = 'PENALISATION' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      INCREMENT = _F{ LIST_INST = L_INST } }
FIN()
