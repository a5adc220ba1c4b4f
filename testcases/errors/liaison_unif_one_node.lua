-- Must-fail deck: LIAISON_UNIF on a group of one node, which has no other node to share its value with.
-- EXPECT_ERROR: liaison_unif_one_node\.lua:8: AFFE_CHAR_MECA: LIAISON_UNIF\[1\]\.GROUP_NO: expected two nodes or more \(one value shared among them\), got 1 node
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
-- the group C11 holds one node
CH = AFFE_CHAR_MECA{ MODELE = MO, LIAISON_UNIF = _F{ GROUP_NO = 'C11', DDL = { 'DX', 'DY' } } }
FIN()
