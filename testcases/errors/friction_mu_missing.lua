-- Must-fail deck: FROTTEMENT='COULOMB' without the zone's COULOMB.
-- EXPECT_ERROR: friction_mu_missing\.lua:7: DEFI_CONTACT: ZONE\[1\]\.COULOMB: expected the friction coefficient mu \(>= 0\) with FROTTEMENT='COULOMB', got none
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', FROTTEMENT = 'COULOMB', ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF' } }
FIN()
