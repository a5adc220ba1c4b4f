-- Must-fail deck: the contact problem of testcases/contact_step_subdivision.lua without
-- ECHEC/DECOUPE. A first STAT_NON_LINE up to INST 0.25 converges and is written by
-- IMPR_RESU (FICHIER='before.rmed'); the second one converges at 0.25 and then fails on the
-- step 0.25 -> 1 (Newton needs more than ITER_GLOB_MAXI = 6 iterations). The message names
-- the instant, the loop and the last residuals, how many steps converged, and where they were
-- saved; the exit status is 3. tests/unit/commands/robustness_test.cpp runs this deck and reads
-- back before.rmed (intact) and the saved converged step.
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: contact_step_no_subdivision\.lua:26: STAT_NON_LINE: Newton did not converge at instant 1\.000000e\+00 within ITER_GLOB_MAXI = 6 iterations
-- EXPECT_ERROR: last residuals: RESI_GLOB_RELA = [0-9.e+-]+, RESI_GLOB_MAXI = [0-9.e+-]+
-- EXPECT_ERROR: loop: Newton \(contact/geometry fixed-point pass [0-9]+\)
-- EXPECT_ERROR: failed in step 2 of 2 \[2\.500000e-01, 1\.000000e\+00\]; 1 step\(s\) converged before, the last at instant 2\.500000e-01 \(NUME_ORDRE 1\)
-- EXPECT_ERROR: the 1 converged step\(s\) are saved in .*contact_step_no_subdivision_converged\.rmed
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'NEWTON',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 0.25, 1.0 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
local function solve(inst_fin)
  return STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                        EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                        COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L, INST_FIN = inst_fin },
                        CONVERGENCE = _F{ ITER_GLOB_MAXI = 6 } }
end
BEFORE = solve(0.25)
IMPR_RESU{ FORMAT = 'MED', FICHIER = 'before.rmed', RESU = _F{ RESULTAT = BEFORE } }
RESU = solve(1.0)
FIN()
