-- Must-fail deck: the glued blocks of testcases/solver_singularity.lua's (1), the upper one 1e10
-- times softer than the lower one, which hangs from it; NPREC = 12 lets MUMPS factorise it. Its
-- solve leaves a relative residual of 3e-6 after refinement, above the 1e-6 every direct solve
-- must reach unless SOLVEUR RESI_RELA says otherwise: the run must stop, blame the accuracy (the
-- stiffness is regular, no contact) and name RESI_RELA (tests/decks/mumps_resi_rela_unchecked.lua
-- goes on with RESI_RELA = -1).
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: mumps_resi_rela_default\.lua:12: STAT_NON_LINE: the system at instant 1\.0+e\+00 is too ill-conditioned for the accuracy asked of its solve: the linear solver returned no accurate solution \(relative residual of the solve [0-9.e+-]+, [0-9.e+-]+ after iterative refinement; accepted below 1\.000000e-06\)
-- EXPECT_ERROR: the stiffness is regular \(no rigid-body mode\) but its solve did not reach the accuracy asked \(SOLVEUR RESI_RELA of MUMPS; 1e-6 for every direct solve otherwise\)
require('lib.soft_link_scene')(2.0e-4)
-- RESI_RELA absent: 1e-6
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, SOLVEUR = _F{ METHODE = 'MUMPS', NPREC = 12 },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
