-- Must-fail deck: NEWTON REAC_INCR = 0 (keep the previous increment's matrix) is refused rather
-- than run as 1, the driver's policy.
-- EXPECT_ERROR: newton_reac_incr_zero\.lua:13: STAT_NON_LINE: NEWTON\.REAC_INCR: expected 1 \(the matrix formed anew at the first iteration of every increment, as lunaster's driver does\), got 0
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
                      INCREMENT = _F{ LIST_INST = L }, NEWTON = _F{ REAC_INCR = 0 } }
FIN()
