-- Must-fail deck: a friction coefficient given while FROTTEMENT is 'SANS' (its default).
-- EXPECT_ERROR: friction_mu_without_coulomb\.lua:7: DEFI_CONTACT: ZONE\[1\]\.COULOMB: expected no friction keyword with FROTTEMENT='SANS', got a value
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COULOMB = 0.3 } }
FIN()
