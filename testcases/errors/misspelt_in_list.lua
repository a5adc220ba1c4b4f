-- Must-fail deck: a misspelt keyword inside the second occurrence of a factor keyword;
-- the keyword path carries the occurrence number and the hint names the valid keyword.
-- EXPECT_ERROR: misspelt_in_list\.lua:18: STAT_NON_LINE: EXCIT\[2\]\.FONC_MUTL: expected a keyword of EXCIT\[2\], got unknown keyword 'FONC_MUTL'
-- EXPECT_ERROR: did you mean 'FONC_MULT'\?
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
FIXED = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 },
                                                  _F{ GROUP_NO = 'BOTTOM', DY = 0.0 } } }
PUSH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'TOP', DY = -0.01 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- the second EXCIT occurrence misspells FONC_MULT
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM,
                   EXCIT = { _F{ CHARGE = FIXED }, _F{ CHARGE = PUSH, FONC_MUTL = RAMPE } },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
FIN()
