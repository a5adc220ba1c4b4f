-- Must-fail deck: the Gmsh mesh names a physical group EMPTY that holds no element;
-- using it for a pressure is an error that says the group is empty (not unknown).
-- EXPECT_ERROR: mesh_empty_group\.lua:8: AFFE_CHAR_MECA: PRES_REP\[1\]\.GROUP_MA: expected a non-empty cell group, got 'EMPTY', which is empty
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'GMSH', FICHIER = 'meshes/block.msh' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
BC = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'EMPTY', PRES = 1.0e4 } }
FIN()
