-- Benchmark (not a verification deck): ssnp121i_refined.lua with mortar contact (DEFI_CONT,
-- APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN'): the same mesh (V1 50x50x10 HEXA8 under V2
-- 40x40x10 HEXA20, about 3.2e5 unknowns), QUAD4 slave (2500 cells) on QUAD8 master (1600 cells),
-- non-matching. The active slave displacements are eliminated: the system is SPD (SOLVEUR AUTO: CG + BoomerAMG).
-- Generate the mesh next to this deck first:
--   build/lunaster-meshgen --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 10 -o tests/bench/ssnp121i_refined.med
-- then: /usr/bin/time -v build/lunaster run tests/bench/ssnp121i_refined_mortar.lua -q
-- Checks: the analytical values at 1e-8 (mortar passes the patch test to round-off).
-- Runtime label: slow, benchmark.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121i_refined.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'OUI' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }

local checks = {}
local function check(cmp, refe, group, kind)
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = cmp, GROUP_NO = group,
                            TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-8 }
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
