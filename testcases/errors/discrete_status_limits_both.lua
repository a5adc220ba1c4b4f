-- Must-fail deck: the discrete formulation's status loop is bounded either per contact point
-- (ITER_CONT_MULT) or by a number of iterations (ITER_CONT_MAXI), not both.
-- EXPECT_ERROR: discrete_status_limits_both\.lua:10: DEFI_CONTACT: expected at most one of ITER_CONT_MAXI, ITER_CONT_MULT
-- EXPECT_ERROR: got ITER_CONT_MAXI and ITER_CONT_MULT
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
-- Both bounds given: refused, naming the keyword and what is expected.
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', ITER_CONT_MAXI = 50, ITER_CONT_MULT = 4,
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', ALGO_CONT = 'CONTRAINTE' } }
FIN()
