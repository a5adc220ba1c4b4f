-- Must-fail deck: MODL_AXIS = 'NON' given explicitly on an AXIS model: the contact would be
-- integrated per radian (it follows the model) while the deck says plane; refused. Without
-- MODL_AXIS the contact follows the model.
-- EXPECT_ERROR: modl_axis_non_on_axis_model\.lua:10: AFFE_CHAR_MECA: CONTACT\.MODL_AXIS: expected 'OUI' \(or no MODL_AXIS\) on MODELE 'MO', an AXIS model, got 'NON'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/axis_contact_matching.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
CH = AFFE_CHAR_MECA{ MODELE = MO, CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', MODL_AXIS = 'NON' } }
FIN()
