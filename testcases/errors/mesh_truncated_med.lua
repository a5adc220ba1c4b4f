-- Must-fail deck: the first 6000 bytes of a real MED file (meshes/patch_quad4.med,
-- 18923 bytes), as left by an interrupted copy. Reported as a deck error naming the
-- file, never a crash.
-- EXPECT_ERROR: mesh_truncated_med\.lua:8: LIRE_MAILLAGE: mesh file '.*meshes/truncated\.med': .*(truncated|corrupt)
-- EXPECT_STATUS: 2
DEBUT()
-- the file is truncated
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/truncated.med' }
FIN()
