-- Must-fail deck: VERI_NORM = 'OUI' (the default) on a mesh read in parts (PARTITIONNEUR). The thick
-- cylinder meshed mirrored (meshes/axis_cylinder_quad8_cw.med): its end faces BOTTOM and TOP (96 SEG3
-- each) point into the wall; BOTTOM is oriented (ORIE_PEAU_2D), and the group ENDS gathers both. Each
-- cell is counted by the rank owning its first node and the counts are summed over the ranks: the
-- serial run's error, with the same counts and the same first cells, said once on every rank alike
-- (mpi.contact_parts_suite runs this deck under mpirun -np 2 and 3 too).
-- EXPECT_ERROR: veri_norm_parts\.lua:16: AFFE_CHAR_MECA: PRES_REP\[1\]\.GROUP_MA: expected boundary cells whose normal points out of the body they bound \(VERI_NORM = 'OUI'\), got group 'ENDS': 96 of 192 cells point into their body \(M2, M5, M7, \.\.\.\), 96 out of it: mixed orientation$
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/axis_cylinder_quad8_cw.med', PARTITIONNEUR = 'PTSCOTCH' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'BOTTOM' } }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA, CREA_GROUP_MA = _F{ NOM = 'ENDS', GROUP_MA = { 'BOTTOM', 'TOP' } } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'C00', DX = 0.0, DY = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'ENDS', PRES = 1.0e6 } }
FIN()
