-- Must-fail deck: a node group name given to NOEUD; the hint says to use GROUP_NO.
-- EXPECT_ERROR: node_group_as_node\.lua:8: AFFE_CHAR_MECA: DDL_IMPO\[1\]\.NOEUD: expected a node name of the mesh, got 'C00'
-- EXPECT_ERROR: 'C00' is a node group: use GROUP_NO = 'C00'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
BC = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ NOEUD = 'C00', DX = 0.0, DY = 0.0 } }
FIN()
