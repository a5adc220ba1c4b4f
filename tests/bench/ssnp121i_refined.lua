-- Benchmark (not a verification deck): SSNP121 I refined 10 times in every direction, about 1e5 nodes.
-- V1 = [0,1]^3 with 50x50x10 HEXA8, V2 = [0,1]^2 x [1,2] with 40x40x10 HEXA20 (99992 nodes); CONTINUE
-- contact QUAD4 slave (2500 cells, 81 Simpson points each: 202500 contact points) on QUAD8 master
-- (1600 cells), non-matching; about 3.2e5 unknowns. Generate the mesh next to this deck first:
--   build/lunaster-meshgen --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 10 -o tests/bench/ssnp121i_refined.med
-- then: /usr/bin/time -v build/lunaster run tests/bench/ssnp121i_refined.lua -q
-- The answer stays exact (master edges on the Simpson panel boundaries, as in SSNP121 I), so the
-- checks are the analytical values at 1e-6. Runtime label: slow, benchmark.
-- Measured (idle 2-core machine, 2026-11-22): MUMPS 3 min 06 s wall, 240 s user, peak RSS 7.9 GB,
-- 12 checks OK (tests/bench/README.md compares with the code before per-cell contact assembly).
-- UMFPACK (int version) runs out of memory at 12.4 GB, hence SOLVEUR METHODE='MUMPS' (now also
-- the default for contact systems).
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                     ZONE = _F{ GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
                                CONTACT_INIT = 'INTERPENETRE', COEF_CONT = 1000.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST }, SOLVEUR = _F{ METHODE = 'MUMPS' } }

local checks = {}
local function check(cmp, refe, group, kind)
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = cmp, GROUP_NO = group,
                            TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-6 }
end
for _, point in ipairs({ 'A21', 'A22', 'A23', 'A24' }) do
  check('DZ', -0.05, point)
  check('LAGS_C', -1.0e5, point)
end
check('LAGS_C', -1.0e5, 'SURESC', 'MIN')
check('LAGS_C', -1.0e5, 'SURESC', 'MAX')
check('DZ', -0.05, 'SURESC', 'MIN')
check('DZ', -0.05, 'SURESC', 'MAX')
TEST_RESU{ RESU = checks }
FIN()
