-- Must-fail deck: the discrete penalty stiffness E_N is > 0, in both contact syntaxes.
-- EXPECT_ERROR: penalty_zero_discrete\.lua:10: AFFE_CHAR_MECA: CONTACT\.E_N: expected real > 0, got 0
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE',
                     ZONE = _F{ GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB', ALGO_CONT = 'PENALISATION', E_N = 1.0e7 } }
CH = AFFE_CHAR_MECA{ MODELE = MO, CONTACT = _F{ METHODE = 'PENALISATION', E_N = 0.0, GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB' } }
FIN()
