-- Must-fail deck: a LIAISON_DDL whose two terms are the same component of the same node with
-- opposite coefficients, DY(N16) - DY(N16) = 0.1: nothing is left to relate (0 = 0.1).
-- EXPECT_ERROR: liaison_ddl_terms_cancel\.lua:8: AFFE_CHAR_MECA: LIAISON_DDL\[1\]\.COEF_MULT: expected coefficients that do not cancel on one component of one node, got terms that sum to zero on every component
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                     LIAISON_DDL = _F{ NOEUD = { 'N16', 'N16' }, DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 }, COEF_IMPO = 0.1 } }
FIN()
