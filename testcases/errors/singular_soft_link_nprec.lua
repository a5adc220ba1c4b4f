-- Must-fail deck: the SSNP121 glued blocks, the upper one 1e9 times softer than the lower one,
-- which hangs from it and nothing else. The lower block's last pivot loses about 9.3
-- significant digits, more than code_aster's default NPREC = 8: the run must stop naming the
-- digits and NPREC, and say what to change (testcases/solver_singularity.lua runs it with
-- NPREC = 12).
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: singular_soft_link_nprec\.lua:17: STAT_NON_LINE: the stiffness matrix is singular at instant 1\.0+e\+00: the body made of 32 cells has a rigid-body mode \(free to move along DY, detected at node N[0-9]+; a pivot lost 9\.[0-9] significant digits, more than NPREC = 8\)
-- EXPECT_ERROR: if a much softer part holds it \(a stiffness ratio near 1e-8\), raise SOLVEUR NPREC above 8 or set STOP_SINGULIER='NON'
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/glued2d_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
STIFF = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
SOFT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e-3, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'PLAQUE1', MATER = SOFT }, _F{ GROUP_MA = 'PLAQUE2', MATER = STIFF } } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
