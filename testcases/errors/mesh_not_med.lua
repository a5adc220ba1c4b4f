-- Must-fail deck: a text file named .med; the message names the file and says it is
-- not MED, with a hint for Gmsh files.
-- EXPECT_ERROR: mesh_not_med\.lua:7: LIRE_MAILLAGE: mesh file '.*meshes/not_a_mesh\.med': not a MED file
-- EXPECT_ERROR: FORMAT='GMSH'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/not_a_mesh.med' }
FIN()
