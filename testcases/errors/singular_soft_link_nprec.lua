-- Must-fail deck: the SSNP121 glued blocks, the upper one 1e9 times softer than the lower one,
-- which hangs from it and nothing else. The lower block's last pivot loses about 9.3
-- significant digits, more than code_aster's default NPREC = 8: the run must stop naming the
-- digits and NPREC, and say what to change (testcases/solver_singularity.lua runs it with
-- NPREC = 12).
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: singular_soft_link_nprec\.lua:10: STAT_NON_LINE: the stiffness matrix is singular at instant 1\.0+e\+00: the body made of 32 cells has a rigid-body mode \(free to move along DY, detected at node N[0-9]+; a pivot lost 9\.[0-9] significant digits, more than NPREC = 8\)
-- EXPECT_ERROR: if a much softer part holds it \(a stiffness ratio near 1e-8\), raise SOLVEUR NPREC above 8 or set STOP_SINGULIER='NON'
require('lib.soft_link_scene')(2.0e-3)
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
