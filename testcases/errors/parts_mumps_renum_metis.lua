-- Must-fail deck: on a mesh read in parts, MUMPS's RENUM = 'METIS' (an ordering lunaster computes
-- from the whole pattern on one process) is refused, naming RENUM: the engine refuses the ordering
-- in its own words and commands/failures.cpp names the keyword and its values.
-- EXPECT_ERROR: parts_mumps_renum_metis\.lua:15: STAT_NON_LINE: MUMPS: the METIS \(nested dissection of the node graph\) ordering asked for \(RENUM\) is computed from the whole matrix's pattern on one process, which a mesh in parts does not gather
-- EXPECT_ERROR: choose RENUM = 'AMD', 'AMF', 'QAMD', 'PORD' or 'AUTO', or read the mesh whole
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/block_hexa8_12.med', PARTITIONNEUR = 'PTSCOTCH' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e8 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                   INCREMENT = _F{ LIST_INST = L }, SOLVEUR = _F{ METHODE = 'MUMPS', RENUM = 'METIS' } }
FIN()
