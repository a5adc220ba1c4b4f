-- SOLVEUR RENUM='METIS' and MATR_DISTRIBUEE under mpirun (tests/mpi/mpi_runs.py, errors case):
-- the same block solved twice with MUMPS.
-- 1. MATR_DISTRIBUEE='OUI' (the default), RENUM='METIS': the model is shared among the ranks,
--    each holding its own columns; they send their patterns to rank 0, which orders the whole
--    matrix by METIS and gives the order to MUMPS. The log says "model shared among 2 ranks"
--    and names the ordering.
-- 2. MATR_DISTRIBUEE='NON': the whole system on every rank, MUMPS reads rank 0's copy.
-- Both give the serial run's answer. Plane strain block under a pressure, NU = 0: DY at the top
-- = -p H / E.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../../testcases/meshes/patch_quad4.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'TOP' } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
LOAD = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                       PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e4 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
for _, solveur in ipairs({ { METHODE = 'MUMPS', RENUM = 'METIS' }, { METHODE = 'MUMPS', MATR_DISTRIBUEE = 'NON' } }) do
  R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = LOAD }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                     SOLVEUR = _F(solveur), INCREMENT = _F{ LIST_INST = L } }
  TEST_RESU{ RESU = { _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DY', TYPE_TEST = 'MIN', GROUP_NO = 'TOP',
                          REFERENCE = 'ANALYTIQUE', VALE_REFE = -5.0e-3, PRECISION = 1.0e-10 },
                      _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DY', TYPE_TEST = 'MAX', GROUP_NO = 'TOP',
                          REFERENCE = 'ANALYTIQUE', VALE_REFE = -5.0e-3, PRECISION = 1.0e-10 } } }
end
FIN()
