-- Must-fail deck: the mesh file does not exist; the message names the file.
-- EXPECT_ERROR: mesh_missing_file\.lua:5: LIRE_MAILLAGE: mesh file '.*meshes/no_such_mesh\.med': no such file
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/no_such_mesh.med' }
FIN()
