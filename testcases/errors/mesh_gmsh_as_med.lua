-- Must-fail deck: a Gmsh file read with FORMAT='MED'.
-- EXPECT_ERROR: mesh_gmsh_as_med\.lua:6: LIRE_MAILLAGE: mesh file '.*meshes/block\.msh': not a MED file
-- EXPECT_ERROR: use FORMAT='GMSH' for \.msh
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/block.msh' }
FIN()
