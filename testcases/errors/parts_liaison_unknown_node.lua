-- Must-fail deck: a LIAISON_DDL node name that no part of a mesh read in parts (PARTITIONNEUR) holds.
-- On a mesh in parts each relation is read whole on every rank, its nodes found by the ranks holding
-- them (docs/distributed-model.md, step 5): a name none holds is the serial run's error, said once,
-- on every rank alike (mpi.contact_parts_suite runs this deck under mpirun -np 2 and 3 too).
-- EXPECT_ERROR: parts_liaison_unknown_node\.lua:12: AFFE_CHAR_MECA: LIAISON_DDL\[2\]\.NOEUD: expected a node name of the mesh, got 'N99999'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/block_hexa8_12.med', PARTITIONNEUR = 'PTSCOTCH' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     LIAISON_DDL = { _F{ NOEUD = { 'N50', 'N337' }, DDL = { 'DX', 'DX' }, COEF_MULT = { 1.0, -1.0 },
                                         COEF_IMPO = 0.0 },
                                     _F{ NOEUD = { 'N50', 'N99999' }, DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 },
                                         COEF_IMPO = 0.0 } } }
FIN()
