-- Must-fail deck: a node name that the mesh does not have; the hint is the closest
-- node name of the mesh.
-- EXPECT_ERROR: unknown_node\.lua:9: AFFE_CHAR_MECA: DDL_IMPO\[1\]\.NOEUD: expected a node name of the mesh, got 'NN12'
-- EXPECT_ERROR: did you mean 'N12'\?
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
BC = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ NOEUD = 'NN12', DX = 0.0, DY = 0.0 } }
FIN()
