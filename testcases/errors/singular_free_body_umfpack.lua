-- Must-fail deck: a block loaded by a pressure with no Dirichlet condition and no
-- contact (rigid-body modes), solved with SOLVEUR METHODE='UMFPACK'. The run stops with
-- a SolveError naming the body (cell group BLOCK) and a free direction, never a
-- solver crash or a NaN field.
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: singular_free_body_umfpack\.lua:17: STAT_NON_LINE: the stiffness matrix is singular at instant 1\.0+e\+00
-- EXPECT_ERROR: the body BLOCK \(9 cells\) has a rigid-body mode \(free to move along D[XY], detected at node
-- EXPECT_ERROR: add DDL_IMPO
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'TOP' } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
LOAD = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e4 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = LOAD }, SOLVEUR = _F{ METHODE = 'UMFPACK' },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
