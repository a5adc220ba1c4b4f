-- Must-fail deck: a Gmsh mesh with a 9-node quadrangle (Gmsh type 10), which lunaster
-- does not support; the message names the file, the type and the element.
-- EXPECT_ERROR: mesh_unsupported_cell\.lua:7: LIRE_MAILLAGE: Gmsh file '.*meshes/unsupported_cell\.msh': unsupported element type 10 \(element 5\)
-- EXPECT_STATUS: 2
DEBUT()

MA = LIRE_MAILLAGE{ FORMAT = 'GMSH', FICHIER = 'meshes/unsupported_cell.msh' }
FIN()
