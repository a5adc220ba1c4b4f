-- SSNP121 A with mortar contact, spelt as code_aster 17 writes it: DEFI_CONT and
-- MECA_NON_LINE{ CONTACT = _F{ DEFINITION = CONT } } (the same engine as STAT_NON_LINE, the
-- same results: the VALE_CALC are those of STAT_NON_LINE with the same contact definition).
-- Purpose: non-matching mortar contact, 12 SEG2 slave (AB) on 11 SEG2 master (EF), dual
--          multipliers, active slave displacements eliminated (SPD system, CHOLMOD),
--          CONTACT_INIT='NON' as in SSNP121 A. Every MECA_NON_LINE keyword is spelt out once.
-- Reference: analytical, uniform strain -0.05 in both blocks: LAGS_C = E*eps = -1e5 Pa everywhere
--            on AB, DY = -0.05 m on AB and EF, SIYY = -1e5 Pa on both sides. Units SI.
-- code_aster gets 0.08 % (A, B) and 0.35 % (O) with CONTINUE; mortar passes the patch test.
-- lunaster: errors at round-off (below 1e-13); PRECISION 1e-8.
-- Runtime label: fast, contact, mortar.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO, REAC_GEOM = 'AUTOMATIQUE', ITER_GEOM_MAXI = 10, RESI_GEOM = 0.01,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                             ALGO_CONT = 'LAGRANGIEN', COEF_CONT = 100.0, CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 2 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = MECA_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = _F{ DEFINITION = CONT },
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = { _F{ RELATION = 'ELAS', DEFORMATION = 'PETIT', GROUP_MA = 'PLAQUE1' },
                                       _F{ RELATION = 'ELAS', TOUT = 'OUI' } },
                      INCREMENT = _F{ LIST_INST = L_INST, INST_INIT = 0.5, INST_FIN = 1.0 },
                      NEWTON = _F{ MATRICE = 'TANGENTE', REAC_ITER = 1 },
                      CONVERGENCE = _F{ RESI_GLOB_RELA = 1e-10, RESI_GLOB_MAXI = 1e-6, ITER_GLOB_MAXI = 20 },
                      SOLVEUR = _F{ METHODE = 'AUTO' } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }

-- VALE_CALC: lunaster's own values from a real run (every one printed as the exact value to 13 digits).
local calc = { LAGS_C = -1.000000000000e+05, DY = -5.000000000000e-02, SIYY = -1.000000000000e+05 }
local checks = {}
local function check(field, group, cmp, refe, calc, kind)
  checks[#checks + 1] = _F{ RESULTAT = RESU, INST = 1.0, NOM_CHAM = field, GROUP_NO = group, NOM_CMP = cmp,
                            TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-8,
                            VALE_CALC = calc }
end
for _, point in ipairs({ 'A', 'O', 'B' }) do
  check('DEPL', point, 'LAGS_C', -1.0e5, calc.LAGS_C)
  check('DEPL', point, 'DY', -0.05, calc.DY)
end
for _, kind in ipairs({ 'MIN', 'MAX' }) do
  check('DEPL', 'AB', 'LAGS_C', -1.0e5, calc.LAGS_C, kind)
  check('DEPL', 'AB', 'DY', -0.05, calc.DY, kind)
  check('DEPL', 'EF', 'DY', -0.05, calc.DY, kind)
  check('SIGM_NOEU', 'AB', 'SIYY', -1.0e5, calc.SIYY, kind)
  check('SIGM_NOEU', 'EF', 'SIYY', -1.0e5, calc.SIYY, kind)
end
TEST_RESU{ RESU = checks }
FIN()
