-- Must-fail deck: MODL_AXIS = 'OUI' asks for an axisymmetric model, which lunaster does
-- not have yet: refused rather than computed as a plane model.
-- EXPECT_ERROR: modl_axis_oui\.lua:9: AFFE_CHAR_MECA: CONTACT\.MODL_AXIS: expected 'NON' \(axisymmetric models are not supported yet\), got 'OUI'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO, CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', MODL_AXIS = 'OUI' } }
FIN()
