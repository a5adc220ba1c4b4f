-- Must-fail deck: a Gmsh mesh whose cell 6 lists its nodes clockwise (negative
-- Jacobian); the message names the file and the cell.
-- EXPECT_ERROR: mesh_inverted_cell\.lua:7: LIRE_MAILLAGE: .*inverted_cell\.msh
-- EXPECT_ERROR: M6
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'GMSH', FICHIER = 'meshes/inverted_cell.msh' }
FIN()
