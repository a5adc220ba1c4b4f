-- Must-fail deck: ALGO_RESO_CONT = 'NEWTON' updates contact statuses inside Newton; only
-- the continuous formulation does that. The discrete one settles its active set between
-- Newton solves, so 'NEWTON' is refused rather than accepted and run as 'POINT_FIXE'.
-- EXPECT_ERROR: discrete_algo_reso_cont_newton\.lua:10: DEFI_CONTACT: ALGO_RESO_CONT: expected 'POINT_FIXE' \(the discrete formulation updates its contact statuses between Newton solves only\), got 'NEWTON'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', ALGO_RESO_CONT = 'NEWTON',
                     ZONE = _F{ GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB' } }
FIN()
