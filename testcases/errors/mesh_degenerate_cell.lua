-- Must-fail deck: a Gmsh mesh whose QUAD4 cell 6 lists node 6 twice (two corners at one
-- point: zero Jacobian there, a collapsed cell); the message names the file and the cell.
-- EXPECT_ERROR: mesh_degenerate_cell\.lua:8: LIRE_MAILLAGE: .*degenerate_cell\.msh
-- EXPECT_ERROR: M6
-- EXPECT_ERROR: no two of their corners are the same node
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'GMSH', FICHIER = 'meshes/degenerate_cell.msh' }
FIN()
