-- Must-fail deck: the rotation axis through POIN_1 and POIN_2 needs two distinct points.
-- EXPECT_ERROR: rotation_axis_zero\.lua:6: MODI_MAILLAGE: ROTATION\[2\]\.POIN_2: expected a point other than POIN_1, got \{ 0, 0, 1 \}
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121d.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA,
                    ROTATION = { _F{ POIN_1 = { 0.0, 0.0, 1.0 }, DIR = { 1.0, 1.0, 0.0 }, ANGLE = 10.0 },
                                 _F{ POIN_1 = { 0.0, 0.0, 1.0 }, POIN_2 = { 0.0, 0.0, 1.0 }, ANGLE = 10.0 } } }
FIN()
