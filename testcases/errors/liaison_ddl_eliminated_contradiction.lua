-- Must-fail deck: two LIAISON_DDL solved for one unknown each (SOLVEUR ELIM_LAGR = 'OUI'),
-- DX(C11) = DX(C00) and DX(C11) = DX(C10) - 0.1. The first is solved for DX(C11); put into the
-- second, it leaves DX(C10) - DX(C00) = 0.1 between two unknowns DDL_IMPO holds at 0: the
-- relations and the imposed values contradict each other. The elimination used to drop the
-- second relation without a word (DX(C11) = 0, the relation not met).
-- EXPECT_ERROR: liaison_ddl_eliminated_contradiction\.lua:20: STAT_NON_LINE: LIAISON_DDL\[2\] of CHARGE 'CH' relates imposed unknowns only \(once the relations before it are solved for their unknowns\), and their imposed values contradict it at t = 1: its terms sum to 0, its right-hand side is 0\.1; change one of the imposed values it relates, or remove the relation if the deck wrote it
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 1.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                     LIAISON_DDL = { _F{ GROUP_NO = { 'C11', 'C00' }, DDL = { 'DX', 'DX' }, COEF_MULT = { 1.0, -1.0 },
                                         COEF_IMPO = 0.0 },
                                     _F{ GROUP_NO = { 'C11', 'C10' }, DDL = { 'DX', 'DX' }, COEF_MULT = { -1.0, 1.0 },
                                         COEF_IMPO = 0.1 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L },
                   SOLVEUR = _F{ METHODE = 'MUMPS', ELIM_LAGR = 'OUI' } }
FIN()
