-- Must-fail deck: a unit cube of 12^3 HEXA8 clamped at the bottom, pressed on top, solved by MUMPS in
-- block low rank (ACCELERATION = 'LR') with LOW_RANK_SEUIL = 0.5, far coarser than any study would
-- ask: the compression drops a fifth of the factor entries, and the four refinement steps of
-- POSTTRAITEMENTS = 'AUTO' do not take the solve to the accuracy every direct solve must reach
-- (RESI_RELA). The error says so and names the low-rank setting first, with what to do.
-- EXPECT_ERROR: mumps_low_rank_too_coarse\.lua:17: STAT_NON_LINE: the system at instant 1\.0+e\+00, factorised approximately as asked \(in block low rank\), could not be solved to the accuracy asked: the linear solver returned no accurate solution
-- EXPECT_ERROR: SOLVEUR ACCELERATION='LR' compressed the factors too coarsely for this system: lower LOW_RANK_SEUIL \(1e-9 to 1e-12 are usual\), use POSTTRAITEMENTS='FORCE', or ACCELERATION='FR' \(full rank\)
-- EXPECT_STATUS: 3
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/block_hexa8_12.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e8 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                   INCREMENT = _F{ LIST_INST = L },
                   SOLVEUR = _F{ METHODE = 'MUMPS', ACCELERATION = 'LR', LOW_RANK_SEUIL = 0.5 } }
FIN()
