-- Must-fail deck: discrete friction on the active-set (CONTRAINTE) contact, which code_aster refuses too.
-- EXPECT_ERROR: friction_discrete_contrainte\.lua:7: DEFI_CONTACT: ZONE\[1\]\.ALGO_CONT: expected 'PENALISATION' with FROTTEMENT='COULOMB' and FORMULATION='DISCRETE', got 'CONTRAINTE'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', FROTTEMENT = 'COULOMB', ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COULOMB = 0.3, E_T = 1e13 } }
FIN()
