-- Must-fail deck: a setting of code_aster's ALGO_CONT='GCP' (here its preconditioner) without GCP
-- sets nothing lunaster runs: refused, not ignored.
-- EXPECT_ERROR: contact_gcp_setting_alone\.lua:10: DEFI_CONTACT: PRE_COND: expected no setting of ALGO_CONT='GCP'
-- EXPECT_ERROR: it sets code_aster's projected conjugate gradient, which no zone asks for
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', PRE_COND = 'DIRICHLET',
                     ZONE = _F{ GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB' } }
FIN()
