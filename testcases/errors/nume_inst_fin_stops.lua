-- Must-fail deck: INCREMENT NUME_INST_FIN = 2 stops the computation at the list's index 2 (t = 1;
-- the list's first time is index 0): the result holds NUME_ORDRE 0 to 2 and no 3.
-- EXPECT_ERROR: nume_inst_fin_stops\.lua:15: TEST_RESU: RESU\[1\]\.NUME_ORDRE: expected a numéro d'ordre stored in the result \(0\.\.2\), got 3
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                               _F{ GROUP_NO = { 'GH', 'AB' }, DX = 0.0, DY = 0.0 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.5, NOMBRE = 3 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, EXCIT = _F{ CHARGE = CHA1 },
                      INCREMENT = _F{ LIST_INST = L, NUME_INST_FIN = 2 } }
TEST_RESU{ RESU = _F{ RESULTAT = RESU, NUME_ORDRE = 3, NOM_CHAM = 'DEPL', GROUP_NO = 'D', NOM_CMP = 'DY', VALE_CALC = -0.1 } }
FIN()
