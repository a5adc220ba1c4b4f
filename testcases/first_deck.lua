-- A first deck: a 1 m x 1 m block in plane strain, free to slide on its floor (BOTTOM) and on its
-- left wall (LEFT), pressed on TOP by P. Exact solution: SIYY = -P everywhere and the floor
-- pushes back with P times the width, P N per metre of thickness. Mesh: first_deck.med, made by
--   build/lunaster-meshgen --block quad4:4 -o first_deck.med
DEBUT()
P   = 1.0e5                                                      -- pressure on TOP, Pa
MA  = LIRE_MAILLAGE{ FORMAT = 'MED' }                            -- unit 20: first_deck.med
MO  = AFFE_MODELE{ MAILLAGE = MA,
                   AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
CM  = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH  = AFFE_CHAR_MECA{ MODELE = MO,
                      DDL_IMPO = { _F{ GROUP_MA = 'BOTTOM', DY = 0.0 }, _F{ GROUP_MA = 'LEFT', DX = 0.0 } },
                      PRES_REP = _F{ GROUP_MA = 'TOP', PRES = P } }
L   = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R   = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                     COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
R   = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = 'SIGM_NOEU', FORCE = 'REAC_NODA' }
IMPR_RESU{ FORMAT = 'MED', RESU = _F{ RESULTAT = R } }           -- out/first_deck/first_deck_80.rmed
TEST_RESU{ RESU = {
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', NOM_CMP = 'SIYY', TYPE_TEST = 'MIN',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -P, PRECISION = 1.0e-10 },
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', NOM_CMP = 'SIYY', TYPE_TEST = 'MAX',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -P, PRECISION = 1.0e-10 },
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'REAC_NODA', NOM_CMP = 'DY', TYPE_TEST = 'SOMM',
      GROUP_NO = 'BOTTOM', REFERENCE = 'ANALYTIQUE', VALE_REFE = P * 1.0, PRECISION = 1.0e-10 } } }
FIN()
