-- Must-fail deck: FORCE_FACE loads the faces of 3D elements (code_aster applies it to a face of a
-- volume element); a 2D model's boundary is made of edges, loaded by FORCE_CONTOUR.
-- EXPECT_ERROR: force_face_on_2d_model\.lua:8: AFFE_CHAR_MECA: FORCE_FACE\[1\]: expected a 3D model, got a 2D model
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO, FORCE_FACE = _F{ GROUP_MA = 'TOP', FY = -1.0e5 } }
FIN()
