-- Must-fail deck: a Gmsh mesh whose QUAD4 cell 6 lists its corners (1,0) (2,0) (1,1) (2,1):
-- a bow-tie whose Jacobian changes sign, which no node order can repair (a cell listed
-- clockwise is reoriented and accepted); the message names the file and the cell.
-- EXPECT_ERROR: mesh_tangled_cell\.lua:8: LIRE_MAILLAGE: .*tangled_cell\.msh': 1 tangled or degenerate cell
-- EXPECT_ERROR: M6 \(QUAD4\)
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'GMSH', FICHIER = 'meshes/tangled_cell.msh' }
FIN()
