-- Must-fail deck: MODL_AXIS = 'OUI' declares axisymmetric contact, but MODELE is a plane (D_PLAN)
-- model: the contact measures follow the model, so a deck saying otherwise was written for another
-- model and is refused rather than computed as a plane model.
-- EXPECT_ERROR: modl_axis_oui\.lua:10: AFFE_CHAR_MECA: CONTACT\.MODL_AXIS: expected 'NON' \(or no MODL_AXIS\) on MODELE 'MO', a plane \(D_PLAN/C_PLAN\) model \(MODL_AXIS = 'OUI' needs AFFE_MODELE MODELISATION = 'AXIS'\), got 'OUI'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO, CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', MODL_AXIS = 'OUI' } }
FIN()
