-- SOLVEUR POSTTRAITEMENTS of MUMPS: how much iterative refinement each direct solve gets. A serial
-- deck of the CTest suite, not of testcases/, for the reason mumps_resi_rela_unchecked.lua gives
-- (its scene: answers exact only to a condition number near 1e10, which another pivot order on two
-- MPI ranks moves beyond the 1e-8 of the rank comparison).
-- Scene: mumps_resi_rela_unchecked.lua's, an assembly of two blocks 1e10 apart in stiffness
-- translated by DY = -0.1 (NPREC = 12, RESI_RELA = -1: no check of the solve itself). The first
-- solve leaves a relative residual of about 3e-6 that refinement lowers. Three runs:
--   RSANS: POSTTRAITEMENTS = 'SANS', no refinement (the log line of the instant names no step);
--   RMINI: 'MINI', two steps (code_aster's ICNTL(10) = -2; the log says 2 refinement steps);
--   RAUTO: 'AUTO' (code_aster's default), up to 4 steps until the solve is backward stable or a
--          step gains nothing (the log says how many).
-- Then the same assembly with both blocks stiff (a well-conditioned system, solved backward stable
-- straight from the factors), two runs: 'AUTO' takes no step; 'FORCE' refines all the same, until
-- a step gains nothing (10 at most).
-- tests/CMakeLists.txt checks the five log lines in that order (test log.mumps_posttraitements).
-- Reference: analytical, DY = -0.1 everywhere. What we get, in the run this deck was written
-- from: without refinement 7.6e-6 (MIN over GH) and 1.3e-5 (MAX) off; with refinement
-- 6.1e-6 and 1.1e-5. The tolerance is 1e-4, what the conditioning allows; the well-conditioned
-- runs are exact to round-off (checked at 1e-10). Units SI.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../../testcases/meshes/glued2d_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
STIFF = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
SOFT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e-4, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'PLAQUE1', MATER = SOFT }, _F{ GROUP_MA = 'PLAQUE2', MATER = STIFF } } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
local runs = {}
for _, post in ipairs({ 'SANS', 'MINI', 'AUTO' }) do
  runs[post] = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                              SOLVEUR = _F{ METHODE = 'MUMPS', NPREC = 12, RESI_RELA = -1.0, POSTTRAITEMENTS = post },
                              COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
end
local checks = {}
for _, post in ipairs({ 'SANS', 'MINI', 'AUTO' }) do
  for _, kind in ipairs({ 'MIN', 'MAX' }) do
    checks[#checks + 1] = _F{ RESULTAT = runs[post], NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'GH', NOM_CMP = 'DY',
                              TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1, PRECISION = 1.0e-4 }
  end
end
CM2 = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = STIFF } }
for _, post in ipairs({ 'AUTO', 'FORCE' }) do
  local r = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM2, EXCIT = _F{ CHARGE = CH },
                           SOLVEUR = _F{ METHODE = 'MUMPS', POSTTRAITEMENTS = post },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
  for _, kind in ipairs({ 'MIN', 'MAX' }) do
    checks[#checks + 1] = _F{ RESULTAT = r, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'GH', NOM_CMP = 'DY',
                              TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1, PRECISION = 1.0e-10 }
  end
end
TEST_RESU{ RESU = checks }
FIN()
