-- Must-fail deck: discrete friction without its tangential stiffness E_T.
-- EXPECT_ERROR: friction_discrete_e_t_missing\.lua:7: DEFI_CONTACT: ZONE\[1\]\.E_T: expected the tangential penalty stiffness \(N/m\) with FROTTEMENT='COULOMB', got none
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', FROTTEMENT = 'COULOMB', ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COULOMB = 0.3, ALGO_CONT = 'PENALISATION', E_N = 1e14 } }
FIN()
