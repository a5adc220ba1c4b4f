-- Must-fail deck: code_aster's COEF_MATR_FROT (a factor on its symmetric approximation of the friction matrix), refused.
-- EXPECT_ERROR: friction_coef_matr_frot\.lua:7: DEFI_CONTACT: ZONE\[1\]\.COEF_MATR_FROT: expected no such setting, got a value
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', FROTTEMENT = 'COULOMB', ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COULOMB = 0.3, ALGO_CONT = 'PENALISATION', E_N = 1e14, E_T = 1e13, COEF_MATR_FROT = 0.9 } }
FIN()
