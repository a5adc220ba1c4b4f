-- Must-fail deck: a block held in DY only (BOTTOM DY = 0, TOP DY imposed), nothing in
-- DX: a rigid translation along DX remains, under a load that is consistent with it
-- (zero in DX), so a solver could return some solution. With METHODE='MUMPS' the
-- run must stop naming the body BLOCK and the direction DX.
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: singular_free_direction_mumps\.lua:16: STAT_NON_LINE: the stiffness matrix is singular at instant 1\.0+e\+00
-- EXPECT_ERROR: the body BLOCK \(9 cells\) has a rigid-body mode \(free to move along DX, detected at node
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
BC = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = -0.01 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = BC }, SOLVEUR = _F{ METHODE = 'MUMPS' },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
