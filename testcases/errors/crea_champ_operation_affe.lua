-- Must-fail deck: CREA_CHAMP OPERATION = 'AFFE' (a field from constants) is refused by name.
-- EXPECT_ERROR: crea_champ_operation_affe\.lua:12: CREA_CHAMP: OPERATION: expected 'EXTR' \(a field taken out of a result\), got 'AFFE'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                               _F{ GROUP_NO = { 'GH', 'AB' }, DX = 0.0, DY = 0.0 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.5, NOMBRE = 3 } }
F = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_DEPL_R' }
FIN()
