-- Must-fail deck: a LIAISON_DDL that relates two imposed unknowns only, DX(C00) + DX(C10) = 0.1,
-- where DDL_IMPO holds both at DX = 0: no unknown is left to satisfy it and the imposed values
-- contradict it (0 against 0.1). With a multiplier (ELIM_LAGR = 'NON', the default) such a
-- relation gets none and used to be dropped without a word.
-- EXPECT_ERROR: liaison_ddl_imposed_contradiction\.lua:17: STAT_NON_LINE: LIAISON_DDL\[1\] of CHARGE 'CH' relates imposed unknowns only, and their imposed values contradict it at t = 1: its terms sum to 0, its right-hand side is 0\.1; change one of the imposed values it relates, or remove the relation if the deck wrote it
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 1.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                     LIAISON_DDL = _F{ GROUP_NO = { 'C00', 'C10' }, DDL = { 'DX', 'DX' }, COEF_MULT = { 1.0, 1.0 },
                                       COEF_IMPO = 0.1 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L } }
FIN()
