-- AFFE_CHAR_MECA VERI_NORM on the thick-walled cylinder of axis_thick_cylinder.lua (AXIS, Lame:
-- a = 1 <= r <= b = 2, pressure P on the inner face LEFT, ends held axially), meshed mirrored
-- (meshes/axis_cylinder_quad8_cw.med, tools/make_meshes.sh: 96 QUAD8 through the wall): LIRE_MAILLAGE
-- reorients the cells, and the boundary cells, which keep their order, point into the wall.
--   VERI_NORM = 'NON': the pressure is applied on LEFT as it is, pushing against its inward normal,
--     i.e. pulling the wall inward: the problem is linear, so the field is exactly the opposite of
--     Lame's, u_r(r) = -(A r + B / r) (with VERI_NORM = 'OUI', the default, this deck is refused:
--     testcases/errors/veri_norm_axis.lua);
--   MODI_MAILLAGE ORIE_PEAU_2D on LEFT, then the default check passes: u_r = A r + B / r.
--   u_r = A r + B / r,  A = P a^2 / ((b^2 - a^2) 2 (lambda + mu)),  B = P a^2 b^2 / ((b^2 - a^2) 2 mu)
-- Tested: u_r at the inner (C00) and outer (C10) radius, relative tolerance 1e-9. QUAD8 are
-- exact for neither term of u_r, which converges as O(h^4) (axis_thick_cylinder.lua: 2.6e-7,
-- 1.7e-8, 1.0e-9, 2.1e-10 at 16/32/64/96 cells): on these 96 cells the error is 2.1e-10 at C00 and
-- 1.6e-10 at C10, so 1e-9 keeps a margin of 5 over the discretisation error and no more (it is
-- the error on 64 cells); a sign or load error is caught by many orders of magnitude. The values
-- equal axis_thick_cylinder.lua's on the counter-clockwise mesh (VALE_CALC), to all 13 digits.
-- Reference: analytical (Lame). Units SI. Runtime label: fast.
DEBUT()
local E, NU, P, A, B = 2.0e11, 0.3, 1.0e8, 1.0, 2.0
-- Lame's u_r in E and NU: 2 (lambda + mu) = E / ((1 + NU)(1 - 2 NU)), 2 mu = E / (1 + NU).
local function ur(r) return (1 + NU) * P * A * A / (E * (B * B - A * A)) * ((1 - 2 * NU) * r + B * B / r) end
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- VALE_CALC: lunaster's own values from a real run (non-regression): u_r at C00 and C10.
local calc = {
  non = { -9.533333331375e-04, -6.066666665683e-04 },
  orie_peau = { 9.533333331375e-04, 6.066666665683e-04 },
}
for _, case in ipairs({ 'non', 'orie_peau' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/axis_cylinder_quad8_cw.med' }
  if case == 'orie_peau' then MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'LEFT' } } end
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
  -- 'NON' on the inward cells; the default ('OUI') once they are oriented.
  local CH = AFFE_CHAR_MECA{ MODELE = MO, VERI_NORM = case == 'non' and 'NON' or nil,
                             DDL_IMPO = _F{ GROUP_NO = { 'BOTTOM', 'TOP' }, DY = 0.0 },
                             PRES_REP = _F{ GROUP_MA = 'LEFT', PRES = P } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
  local sign = case == 'non' and -1.0 or 1.0
  local checks = {}
  for i, node in ipairs({ 'C00', 'C10' }) do
    checks[i] = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', GROUP_NO = node,
                    REFERENCE = 'ANALYTIQUE', VALE_REFE = sign * ur(node == 'C00' and A or B), PRECISION = 1.0e-9,
                    VALE_CALC = calc[case][i], LEGENDE = case }
  end
  TEST_RESU{ RESU = checks }
end
FIN()
