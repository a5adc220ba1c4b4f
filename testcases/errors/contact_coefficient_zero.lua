-- Must-fail deck: augmentation and penalty coefficients are > 0 (a zero COEF_CONT divides
-- the inactive multiplier equations by zero; a zero or negative penalty holds nothing).
-- EXPECT_ERROR: contact_coefficient_zero\.lua:11: DEFI_CONTACT: ZONE\[1\]\.COEF_CONT: expected real > 0, got 0
-- EXPECT_ERROR: also ZONE\[2\]\.COEF_PENA_CONT: expected real > 0, got -1e\+07
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
-- two zones, one error each
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ZONE = { _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COEF_CONT = 0.0 },
                              _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', ALGO_CONT = 'PENALISATION',
                                  COEF_PENA_CONT = -1.0e7 } } }
FIN()
