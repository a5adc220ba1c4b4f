-- Must-fail deck: a node group that the mesh does not have, in the second occurrence
-- of DDL_IMPO; the hint is the closest group name of the mesh.
-- EXPECT_ERROR: unknown_group_no\.lua:9: AFFE_CHAR_MECA: DDL_IMPO\[2\]\.GROUP_NO: expected a node group of the mesh, got 'BOTOM'
-- EXPECT_ERROR: did you mean 'BOTTOM'\?
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
BC = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTOM', DY = 0.0 } } }
FIN()
