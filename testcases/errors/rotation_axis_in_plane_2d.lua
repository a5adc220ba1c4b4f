-- Must-fail deck: a 2D mesh turns only about z (it must stay in its plane); an axis in the plane
-- would lift it out. The error names the keyword, the axis given and the remedy.
-- EXPECT_ERROR: rotation_axis_in_plane_2d\.lua:9: MODI_MAILLAGE: ROTATION\[1\]\.DIR: expected an axis along z in a 2D mesh
-- EXPECT_ERROR: got the axis \{ 1, 0, 1 \}
-- EXPECT_ERROR: omit DIR and POIN_2 to rotate about z
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ROTATION = _F{ POIN_1 = { 0.0, 0.0 }, DIR = { 1.0, 0.0, 1.0 }, ANGLE = 30.0 } }
FIN()
