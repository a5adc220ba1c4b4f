-- Must-fail deck: LIAISON_DDL with GROUP_NO = 'TOP', a group of four nodes, and two components: a
-- relation has one component and one coefficient per node. The error counts both and says how to
-- name the nodes.
-- EXPECT_ERROR: liaison_ddl_count_mismatch\.lua:10: AFFE_CHAR_MECA: LIAISON_DDL\[1\]\.DDL: expected one component per node \(4 node\(s\) from GROUP_NO\), got 2 component\(s\)
-- EXPECT_ERROR: a GROUP_NO group gives all its nodes: name groups of one node each, or use NOEUD
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     LIAISON_DDL = _F{ GROUP_NO = 'TOP', DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 }, COEF_IMPO = 0.0 } }
FIN()
