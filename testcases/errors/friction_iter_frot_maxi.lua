-- Must-fail deck: ITER_FROT_MAXI bounds code_aster's friction fixed point (ALGO_RESO_FROT='POINT_FIXE'), which lunaster does not have.
-- EXPECT_ERROR: friction_iter_frot_maxi\.lua:7: DEFI_CONTACT: ITER_FROT_MAXI: expected no setting of the friction fixed point, got a value
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', FROTTEMENT = 'COULOMB', ITER_FROT_MAXI = 10, ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COULOMB = 0.3 } }
FIN()
