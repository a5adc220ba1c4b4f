-- Must-fail deck: relations solved for one unknown each (SOLVEUR ELIM_LAGR = 'OUI') where one
-- repeats another. CH1 ties DY(N13) to DY(N14); CH2's LIAISON_UNIF on the top edge ties DY of
-- N14, N15 and N16 to that of N13, the first of the group: its first relation is CH1's again, and
-- no unknown is left to solve it for. The message names the relation by its occurrence, node
-- and charge (it used to say "linear relation 2").
-- EXPECT_ERROR: liaison_unif_redundant\.lua:19: STAT_NON_LINE: LIAISON_UNIF\[1\] \(DY of node N14 equal to node N13's\) of CHARGE 'CH2' is a combination of the relations before it \(with its right-hand side, the same relation or a contradiction\): remove it
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 1.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH1 = AFFE_CHAR_MECA{ MODELE = MO,
                      DDL_IMPO = { _F{ GROUP_NO = 'BOTTOM', DY = 0.0 }, _F{ GROUP_NO = 'C00', DX = 0.0 } },
                      LIAISON_DDL = _F{ NOEUD = { 'N13', 'N14' }, DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 },
                                        COEF_IMPO = 0.0 } }
CH2 = AFFE_CHAR_MECA{ MODELE = MO, LIAISON_UNIF = _F{ GROUP_MA = 'TOP', DDL = 'DY' } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = { _F{ CHARGE = CH1 }, _F{ CHARGE = CH2 } },
                   INCREMENT = _F{ LIST_INST = L }, SOLVEUR = _F{ METHODE = 'MUMPS', ELIM_LAGR = 'OUI' } }
FIN()
