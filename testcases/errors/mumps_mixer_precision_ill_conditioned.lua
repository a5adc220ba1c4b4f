-- Must-fail deck: SOLVEUR MIXER_PRECISION = 'OUI' on a system single precision cannot carry. Two
-- blocks glued along their interface, one 1e10 times softer than the other (E = 2e-4 against 2e6
-- Pa), the stiff edge CD moved by DY = -0.1: the condition number of the system is far beyond the
-- reach of single-precision factors, so the refinement in double precision does not bring the
-- solve to the accuracy every direct solve must reach (RESI_RELA). The error says so and names
-- MIXER_PRECISION first, with what to do. (tests/decks/mumps_posttraitements.lua solves the same
-- scene in double precision.)
-- EXPECT_ERROR: mumps_mixer_precision_ill_conditioned\.lua:20: STAT_NON_LINE: the system at instant 1\.0+e\+00, factorised approximately as asked \(in single precision\), could not be solved to the accuracy asked: the linear solver returned no accurate solution
-- EXPECT_ERROR: SOLVEUR MIXER_PRECISION='OUI' factorised in single precision, too coarse for this system's conditioning: use POSTTRAITEMENTS='FORCE', or MIXER_PRECISION='NON' \(the default\)
-- EXPECT_STATUS: 3
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/glued2d_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
STIFF = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
SOFT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e-4, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'PLAQUE1', MATER = SOFT },
                                            _F{ GROUP_MA = 'PLAQUE2', MATER = STIFF } } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L },
                      SOLVEUR = _F{ METHODE = 'MUMPS', NPREC = 12, MIXER_PRECISION = 'OUI' } }
FIN()
