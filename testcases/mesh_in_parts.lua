-- A mesh read in parts (LIRE_MAILLAGE PARTITIONNEUR = 'PTSCOTCH'): a unit cube of 12^3 HEXA8 clamped
-- at the bottom, pressed on top (1e6 Pa) and on its x = 1 side (2e5 Pa), pulled along y at a corner
-- (5e4 N), the loads ramped over two instants. Every command of linear elasticity that takes a mesh
-- in parts is here (contact on parts: mortar_petsc_in_parts.lua and mpi.contact_parts_suite):
-- DEFI_GROUP, MODI_MAILLAGE, AFFE_*, STAT_NON_LINE, CALC_CHAMP (stresses, nodal forces, reactions),
-- TEST_RESU (a node's value, reductions over groups and the whole mesh), IMPR_RESU (MED, table).
-- Run alone it is one part; under `mpirun -np N lunaster run` each rank holds one part, and the
-- values and files are the serial run's (tests/mpi/mpi_runs.py parts_suite).
-- Reference: the reactions at the clamped nodes balance the loads (statics: their sums are the
-- applied forces, to round-off); the other values are non-regression (VALE_CALC, from a serial
-- run without PARTITIONNEUR). Units SI. Runtime label: fast.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/block_hexa8_12.med', PARTITIONNEUR = 'PTSCOTCH' }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA, CREA_GROUP_NO = _F{ GROUP_MA = 'TOP', NOM = 'TOP_NO' },
                 CREA_GROUP_MA = _F{ NOM = 'SIDES', GROUP_MA = { 'RIGHT', 'TOP' } } }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_3D = _F{ GROUP_MA = { 'TOP', 'RIGHT' } } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e9, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     PRES_REP = { _F{ GROUP_MA = 'TOP', PRES = 1.0e6 }, _F{ GROUP_MA = 'RIGHT', PRES = 2.0e5 } },
                     FORCE_NODALE = _F{ GROUP_NO = 'C111', FY = 5.0e4 } }
RAMP = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 2 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMP },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L },
                   SOLVEUR = _F{ METHODE = 'MUMPS' } }
R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' }, CRITERES = { 'SIEQ_NOEU' },
                FORCE = { 'FORC_NODA', 'REAC_NODA' } }

-- Statics: the reactions on BOTTOM balance the loads at each instant.
local function reaction(inst, cmp, refe)
  return _F{ RESULTAT = R, INST = inst, NOM_CHAM = 'REAC_NODA', NOM_CMP = cmp, TYPE_TEST = 'SOMM',
             GROUP_NO = 'BOTTOM', REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-9,
             CRITERE = 'RELATIF' }
end
TEST_RESU{ RESU = {
  reaction(0.5, 'DX', 1.0e5), reaction(0.5, 'DY', -2.5e4), reaction(0.5, 'DZ', 5.0e5),
  reaction(1.0, 'DX', 2.0e5), reaction(1.0, 'DY', -5.0e4), reaction(1.0, 'DZ', 1.0e6),
} }

-- Non-regression: a node's values (a one-node group, a node name), reductions over groups, over
-- the whole mesh and over a group DEFI_GROUP made.
local function calc(cham, cmp, value, where)
  where.RESULTAT, where.INST, where.NOM_CHAM, where.NOM_CMP, where.VALE_CALC = R, 1.0, cham, cmp, value
  return _F(where)
end
TEST_RESU{ RESU = {
  calc('DEPL', 'DX', -1.018951721e-03, { GROUP_NO = 'C111' }),
  calc('DEPL', 'DY', 2.722510395e-03, { GROUP_NO = 'C111' }),
  calc('DEPL', 'DZ', -1.110918013e-03, { NOEUD = 'N2197' }),
  calc('DEPL', 'DZ', -1.110918013e-03, { GROUP_NO = 'TOP_NO', TYPE_TEST = 'MIN' }),
  calc('DEPL', 'DX', -1.834562592e-04, { GROUP_NO = 'TOP_NO', TYPE_TEST = 'MAX' }),
  calc('SIGM_NOEU', 'SIZZ', -1.111096772e+07, { GROUP_MA = 'SIDES', TYPE_TEST = 'MIN' }),
  calc('SIGM_NOEU', 'SIXY', 6.901313319e+07, { TYPE_TEST = 'SOMM_ABS' }),
  calc('SIEQ_NOEU', 'VMIS', 5.121976708e+07, { TYPE_TEST = 'MAX' }),
  calc('FORC_NODA', 'DZ', -1.000000000e+06, { GROUP_NO = 'TOP_NO', TYPE_TEST = 'SOMM' }),
} }
IMPR_RESU{ FORMAT = 'MED', UNITE = 80, RESU = _F{ RESULTAT = R } }
IMPR_RESU{ FORMAT = 'RESULTAT', UNITE = 8, RESU = _F{ RESULTAT = R, NOM_CHAM = 'DEPL', GROUP_NO = 'C111' } }
FIN()
