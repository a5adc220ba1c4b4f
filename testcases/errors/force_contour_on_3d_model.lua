-- Must-fail deck: FORCE_CONTOUR loads the edges of 2D and AXIS models (code_aster: forces per unit
-- length on the boundary of a 2D domain); a 3D model takes FORCE_FACE or FORCE_ARETE.
-- EXPECT_ERROR: force_contour_on_3d_model\.lua:8: AFFE_CHAR_MECA: FORCE_CONTOUR\[1\]: expected a 2D or AXIS model, got a 3D model
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_hexa8.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CH = AFFE_CHAR_MECA{ MODELE = MO, FORCE_CONTOUR = _F{ GROUP_MA = 'TOP', FZ = -1.0e5 } }
FIN()
