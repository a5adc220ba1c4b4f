-- SOLVEUR ELIM_LAGR = 'OUI' on a run with no linear relation: nothing is left for it to solve for
-- one unknown (DDL_IMPO conditions are always eliminated, as code_aster's ELIM_LAGR = 'OUI' does
-- with them), and the log says so rather than staying silent (test log.elim_lagr_without_relations
-- in tests/CMakeLists.txt). The scene: the glued SSNP121 2D mesh translated by DY = -0.1 through
-- CD, whose answer is exact (DY = -0.1 everywhere, checked at 1e-12). Units SI.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../../testcases/meshes/glued2d_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, SOLVEUR = _F{ ELIM_LAGR = 'OUI' },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
TEST_RESU{ RESU = {
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'GH', NOM_CMP = 'DY', TYPE_TEST = 'MIN',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1, PRECISION = 1.0e-12 },
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'GH', NOM_CMP = 'DY', TYPE_TEST = 'MAX',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1, PRECISION = 1.0e-12 },
} }
FIN()
