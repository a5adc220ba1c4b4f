-- FORCE_CONTOUR, a force per unit length on 2D boundary edges:
-- 1. D_PLAN and C_PLAN, unit square (distorted patch meshes, QUAD4 and QUAD8), symmetry supports
--    (DX = 0 on LEFT, DY = 0 on BOTTOM), TOP loaded by FORCE_CONTOUR FY = -P (the traction's
--    components, whatever the edges' orientation): sigma_yy = -P,
--    C_PLAN: u_y(C11) = -P / E, u_x(C11) = NU P / E;
--    D_PLAN: u_y(C11) = -(1 - NU^2) P / E, u_x(C11) = NU (1 + NU) P / E; base reaction +P.
--    A uniform stress is exact on these meshes and a uniform traction on a straight edge integrates
--    exactly: tolerance 1e-12 (1e-10 for the reaction, a sum of nodal forces).
-- 2. AXIS: the thick cylinder of axis_thick_cylinder.lua (1 <= r <= 2, 96 QUAD8 through the wall,
--    ends held axially) with FORCE_CONTOUR FX = P on the inner face r = 1 in place of PRES_REP
--    PRES = P (the outward normal there is -x): per unit length of the meridian, integrated over
--    r dl per radian as the pressure, so it is the same load. Checked against Lame's u_r at the
--    inner and outer radius at that deck's tolerance (1e-9, its discretisation error 2.1e-10), and
--    against the PRES_REP run's own u_r to 1e-12 (the same nodal forces up to round-off).
-- VALE_CALC (AXIS only): the run's u_r; elsewhere the analytical check at its exact tolerance
-- is the only one (a VALE_CALC equal to the reference would add nothing a run recorded).
-- Reference: analytical. Units SI. Runtime label: fast.
DEBUT()
local E, NU, P = 2.0e11, 0.3, 1.0e8
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
local function solve(MO, CM, loads)
  local excit = {}
  for _, ch in ipairs(loads) do excit[#excit + 1] = _F{ CHARGE = ch } end
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = excit, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                           INCREMENT = _F{ LIST_INST = L } }
  return CALC_CHAMP{ reuse = R, RESULTAT = R, FORCE = 'REAC_NODA' }
end

for _, cell in ipairs({ 'quad4', 'quad8' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_' .. cell .. '.med' }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  for _, model in ipairs({ 'D_PLAN', 'C_PLAN' }) do
    local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = model } }
    local BC = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_MA = 'LEFT', DX = 0.0 },
                                                        _F{ GROUP_MA = 'BOTTOM', DY = 0.0 } },
                               FORCE_CONTOUR = _F{ GROUP_MA = 'TOP', FY = -P } }
    local R = solve(MO, CM, { BC })
    local uy = model == 'C_PLAN' and -P / E or -(1 - NU * NU) * P / E
    local ux = model == 'C_PLAN' and NU * P / E or NU * (1 + NU) * P / E
    local legend = cell .. ' ' .. model
    local function t(cmp, refe)
      return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = cmp, GROUP_NO = 'C11', LEGENDE = legend,
                 REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-12 }
    end
    TEST_RESU{ RESU = { t('DY', uy), t('DX', ux) } }
    local T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'BASE', RESULTAT = R,
                                          NOM_CHAM = 'REAC_NODA', GROUP_NO = 'BOTTOM', RESULTANTE = 'DY',
                                          NUME_ORDRE = 1 } }
    TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', LEGENDE = legend, REFERENCE = 'ANALYTIQUE', VALE_REFE = P,
                PRECISION = 1.0e-10 }
  end
end

-- 2. AXIS thick cylinder (Lame): u_r = A r + B / r.
local A, B = 1.0, 2.0
local LAMBDA, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
local K = P * A * A / (B * B - A * A)
local function ur(r) return K / (2 * (LAMBDA + MU)) * r + K * B * B / (2 * MU) / r end
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/axis_cylinder_quad8.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'LEFT' } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
BC = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = { 'BOTTOM', 'TOP' }, DY = 0.0 } }
-- VALE_CALC: the run's u_r (those of axis_thick_cylinder.lua's QUAD8 PRES_REP case).
local calc = { C00 = 9.533333331375e-04, C10 = 6.066666665683e-04 }
local tabs = {}
for _, kind in ipairs({ 'PRES_REP', 'FORCE_CONTOUR' }) do
  local CH = kind == 'PRES_REP' and AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'LEFT', PRES = P } }
                                or AFFE_CHAR_MECA{ MODELE = MO, FORCE_CONTOUR = _F{ GROUP_MA = 'LEFT', FX = P } }
  local R = solve(MO, CM, { BC, CH })
  local checks = {}
  for _, n in ipairs({ { 'C00', A }, { 'C10', B } }) do  -- in this order: the checks' order is compared
    local node, r = n[1], n[2]
    checks[#checks + 1] = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', GROUP_NO = node,
                              LEGENDE = 'AXIS ' .. kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = ur(r),
                              PRECISION = 1.0e-9, VALE_CALC = calc[node] }
  end
  TEST_RESU{ RESU = checks }
  tabs[kind] = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'C00', RESULTAT = R,
                                           NOM_CHAM = 'DEPL', GROUP_NO = 'C00', NOM_CMP = 'DX', NUME_ORDRE = 1 } }
end
TEST_TABLE{ TABLE = tabs.FORCE_CONTOUR, NOM_PARA = 'DX', LEGENDE = 'AXIS FORCE_CONTOUR = PRES_REP',
            REFERENCE = 'ANALYTIQUE', VALE_REFE = tabs.PRES_REP['DX'][1], PRECISION = 1.0e-12,
            VALE_CALC = calc.C00 }
FIN()
