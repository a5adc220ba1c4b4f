-- Must-fail deck: DEFI_GROUP OPTION = 'PLAN' that no node lies on (the line y = 2, outside the
-- unit square) makes no group: an error naming the group.
-- EXPECT_ERROR: defi_group_plan_empty\.lua:7: DEFI_GROUP: CREA_GROUP_NO\[1\]\.NOM: expected a group of at least one node, got no node within PRECISION of the surface for 'OUTSIDE'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad8.med' }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA, CREA_GROUP_NO = _F{ NOM = 'OUTSIDE', OPTION = 'PLAN', POINT = { 0.0, 2.0 },
                                                                 VECT_NORMALE = { 0.0, 1.0 }, PRECISION = 1.0e-6 } }
FIN()
