-- Must-fail deck: a cell group that the mesh does not have; the hint is the closest
-- group name of the mesh.
-- EXPECT_ERROR: unknown_group_ma\.lua:9: AFFE_MATERIAU: AFFE\[1\]\.GROUP_MA: expected a cell group of the mesh, got 'PLAQE1'
-- EXPECT_ERROR: did you mean 'PLAQUE1'\?
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQE1', 'PLAQUE2' }, MATER = MAT } }
FIN()
