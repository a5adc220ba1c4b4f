-- Must-fail deck: code_aster's projected conjugate gradient (DEFI_CONTACT ALGO_CONT='GCP', as in
-- code_aster's SSNP121L) is refused by name with the algorithm that solves the same problem.
-- EXPECT_ERROR: contact_gcp_refused\.lua:10: DEFI_CONTACT: ZONE\[1\]\.ALGO_CONT: expected 'CONTRAINTE' or 'PENALISATION' with FORMULATION='DISCRETE', got 'GCP'
-- EXPECT_ERROR: ALGO_CONT='CONTRAINTE' \(the active set\) solves the same discrete contact problem exactly
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', RESI_ABSO = 1.0e-8, PRE_COND = 'DIRICHLET',
                     ZONE = _F{ GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB', ALGO_CONT = 'GCP' } }
FIN()
