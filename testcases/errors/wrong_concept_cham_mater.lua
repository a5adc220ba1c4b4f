-- Must-fail deck: a material (mater) given where a material field (cham_mater, from
-- AFFE_MATERIAU) is expected; the message names the concept given.
-- EXPECT_ERROR: wrong_concept_cham_mater\.lua:13: STAT_NON_LINE: CHAM_MATER: expected cham_mater concept, got mater MAT
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
BC = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 },
                                               _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = -0.01 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = MAT, EXCIT = _F{ CHARGE = BC },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
