-- Must-fail deck: the glued blocks of testcases/solver_singularity.lua's (1), the upper one 1e10
-- times softer than the lower one, which hangs from it; NPREC = 12 lets MUMPS factorise it. Its
-- solve leaves a relative residual of 3e-6 after refinement, above the 1e-6 every direct solve
-- must reach unless SOLVEUR RESI_RELA says otherwise: the run must stop, blame the accuracy (the
-- stiffness is regular, no contact) and name RESI_RELA (tests/decks/mumps_resi_rela_unchecked.lua
-- goes on with RESI_RELA = -1).
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: mumps_resi_rela_default\.lua:19: STAT_NON_LINE: the system at instant 1\.0+e\+00 is too ill-conditioned for the accuracy asked of its solve: the linear solver returned no accurate solution \(relative residual of the solve [0-9.e+-]+, [0-9.e+-]+ after iterative refinement; accepted below 1\.000000e-06\)
-- EXPECT_ERROR: the stiffness is regular \(no rigid-body mode\) but its solve did not reach the accuracy asked \(SOLVEUR RESI_RELA of MUMPS; 1e-6 for every direct solve otherwise\)
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/glued2d_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
STIFF = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
SOFT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e-4, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'PLAQUE1', MATER = SOFT }, _F{ GROUP_MA = 'PLAQUE2', MATER = STIFF } } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
-- RESI_RELA absent: 1e-6
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, SOLVEUR = _F{ METHODE = 'MUMPS', NPREC = 12 },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
