-- STAT_NON_LINE NEWTON: how often Newton factorises its matrix.
-- Purpose: (1) REAC_ITER. The SSNP121 A blocks (ssnp121a.med, NU = 0) pressed by DY = -0.1 on CD
--          in two steps, CONTINUE contact with the pairing updated at every Newton iteration
--          (ALGO_RESO_GEOM='NEWTON'): Newton iterates within each step. RESU_1 refactorises at
--          every iteration (REAC_ITER = 1, the default); RESU_0 only at the first iteration of
--          each step and contact pass (REAC_ITER = 0: a modified Newton, old factors with the
--          current residual). Both converge to RESI_GLOB_RELA = 1e-9 and give the same answer: the
--          VALE_CALC below are RESU_1's (recorded from a run), checked on both; RESU_0 agrees to
--          3e-11. The log counts the factorisations of each step: 6 and 6 for RESU_1, 2 and 1 for
--          RESU_0 ("factorisation of iteration 0 reused"), in the same 6 + 6 iterations: the
--          pairing update has no tangent term of its own, so refactorising gains nothing here.
--          (2) MATRICE='ELASTIQUE' without contact: a QUAD4 patch under a ramp of imposed
--          displacement over four steps; the elastic matrix is factorised once for the run
--          instead of once per step, with the same exact answer.
-- Reference: analytical. (1) uniform strain -0.05 at the end: DY = -0.05 m on AB, LAGS_C =
--            E*eps = -1e5 Pa; DY = -0.025 m at INST 0.5 (linear in the load); tolerances 1 %
--            (we get 0.3 %). (2) uniaxial strain EPS t in plane strain, NU = 0: SIYY = E EPS t, the
--            reaction of TOP SIYY x 1 m, SIXX = 0 and DX = 0 on the free face RIGHT, to round-off.
--            Units SI. Runtime label: fast, contact, nonlinear.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'NEWTON',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
                                COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 2 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
local function solve(reac_iter)
  return STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                        EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                        COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L },
                        NEWTON = _F{ MATRICE = 'TANGENTE', REAC_ITER = reac_iter },
                        CONVERGENCE = _F{ RESI_GLOB_RELA = 1.0e-9, ITER_GLOB_MAXI = 40 } }
end
RESU_1 = solve(1)
RESU_0 = solve(0)

local checks = {}
for _, r in ipairs({ RESU_1, RESU_0 }) do
  local function depl(where, cmp, inst, calc, refe)
    return _F{ RESULTAT = r, INST = inst, NOM_CHAM = 'DEPL', GROUP_NO = where, NOM_CMP = cmp, VALE_CALC = calc,
               REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-2 }
  end
  checks[#checks + 1] = depl('O', 'DY', 0.5, -2.498887106727e-02, -0.025)
  checks[#checks + 1] = depl('O', 'DY', 1.0, -4.997816575806e-02, -0.05)
  checks[#checks + 1] = depl('O', 'LAGS_C', 1.0, -1.003585908451e+05, -1.0e5)
  checks[#checks + 1] = depl('A', 'DY', 1.0, -4.999657831991e-02, -0.05)
end
TEST_RESU{ RESU = checks }

-- (2) MATRICE = 'ELASTIQUE', no contact.
local EPS = -0.01
PA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_quad4.med' }
PMO = AFFE_MODELE{ MAILLAGE = PA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
PCM = AFFE_MATERIAU{ MAILLAGE = PA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
PCH = AFFE_CHAR_MECA{ MODELE = PMO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                                 _F{ GROUP_NO = 'TOP', DY = EPS } } }
L4 = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 4 } }
PR = STAT_NON_LINE{ MODELE = PMO, CHAM_MATER = PCM, EXCIT = _F{ CHARGE = PCH, FONC_MULT = RAMPE },
                    INCREMENT = _F{ LIST_INST = L4 }, NEWTON = _F{ MATRICE = 'ELASTIQUE' } }
PR = CALC_CHAMP{ reuse = PR, RESULTAT = PR, CONTRAINTE = 'SIGM_NOEU', FORCE = 'REAC_NODA' }
-- What the solve computes, at every step: the stress E EPS t all over the patch (NU = 0), and the
-- reaction of TOP, that stress over its 1 m (REAC_NODA = B^T sigma: the body pushes on its support);
-- at the end, no stress across and no displacement of the free face RIGHT (NU = 0), zero to round-off
-- on the scale of the stress and of the imposed displacement.
local patch = {}
local function t(inst, field, cmp, where, kind, refe, extra)
  local f = { RESULTAT = PR, INST = inst, NOM_CHAM = field, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = where,
              REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10, LEGENDE = "MATRICE='ELASTIQUE'" }
  for k, v in pairs(extra or {}) do f[k] = v end
  patch[#patch + 1] = _F(f)
end
local SYY = 2.0e6 * EPS
for _, inst in ipairs({ 0.25, 0.5, 0.75, 1.0 }) do
  t(inst, 'SIGM_NOEU', 'SIYY', nil, 'MIN', SYY * inst)
  t(inst, 'SIGM_NOEU', 'SIYY', nil, 'MAX', SYY * inst)
  t(inst, 'REAC_NODA', 'DY', 'TOP', 'SOMM', SYY * inst * 1.0)
end
for _, kind in ipairs({ 'MIN', 'MAX' }) do
  t(1.0, 'SIGM_NOEU', 'SIXX', nil, kind, 0.0, { CRITERE = 'ABSOLU', PRECISION = 1.0e-10 * math.abs(SYY) })
  t(1.0, 'DEPL', 'DX', 'RIGHT', kind, 0.0, { CRITERE = 'ABSOLU', PRECISION = 1.0e-10 * math.abs(EPS) })
end
TEST_RESU{ RESU = patch }
FIN()
