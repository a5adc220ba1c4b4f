-- Thick-walled cylinder under internal pressure in AXIS (Lame): a = 1 <= r <= b = 2, pressure P on the
-- inner face, ends held axially (DY = 0 on BOTTOM and TOP: plane strain, eps_zz = 0). One cell high.
--   u_r = A r + B / r,  A = P a^2 / ((b^2 - a^2) 2 (lambda + mu)),  B = P a^2 b^2 / ((b^2 - a^2) 2 mu)
--   sigma_rr = P a^2/(b^2 - a^2) (1 - b^2/r^2), sigma_tt = P a^2/(b^2 - a^2) (1 + b^2/r^2),
--   sigma_zz = 2 NU P a^2/(b^2 - a^2).
-- Tested at the inner (C00) and outer (C10) radius, each at a relative tolerance a few times the
-- discretisation error the run gives (on the scale of P where the reference is 0):
--   QUAD8, 96 cells through the wall (meshes/axis_cylinder_quad8.med): u_r, and the nodal stresses
--     (SIGM_NOEU) SIXX (radial), SIZZ (hoop), SIYY (axial). Measured rates (16/32/64/96 cells):
--     u_r O(h^4) (2.6e-7, 1.7e-8, 1.0e-9, 2.1e-10), nodal SIXX at r = a O(h^2) (2.6e-3, 6.7e-4,
--     1.7e-4, 7.7e-5): the Gauss-to-node extrapolation is linear (code_aster's rule). Errors at 96
--     cells: u_r 2.1e-10 (C00), 1.6e-10 (C10): tolerance 1e-9; stresses at C00 7.7e-5 (SIXX), 3.5e-5
--     (SIZZ), 2.7e-5 (SIYY): 1e-4; at C10 4.9e-6, 5.7e-6, 1.7e-6: 2e-5.
--   QUAD4, 128 cells (meshes/axis_cylinder_quad4.med): u_r only, error O(h^2) (1.0e-5 at C00, 7.9e-6
--     at C10: tolerance 3e-5); its nodal stresses converge as O(h) (SIXX at r = a: 9.1e-3, 4.5e-3,
--     3.0e-3 at 256/512/768 cells) and do not reach 1e-4 on a mesh of reasonable size.
-- Reference: analytical (Lame). Units SI. Runtime label: fast.
DEBUT()
local E, NU, P, A, B = 2.0e11, 0.3, 1.0e8, 1.0, 2.0
local LAMBDA, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
local K = P * A * A / (B * B - A * A)
local CA, CB = K / (2 * (LAMBDA + MU)), K * B * B / (2 * MU)
local function ur(r) return CA * r + CB / r end
local function srr(r) return K * (1 - B * B / (r * r)) end
local function stt(r) return K * (1 + B * B / (r * r)) end
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- VALE_CALC: lunaster's own values from a real run (non-regression), in the order of the checks below.
local calc = {
  quad8 = { 9.533333331375e-04, -9.999232252080e+07, 1.666608157180e+08, 2.000054795903e+07,
            6.066666665683e-04, 4.891564223211e+02, 6.666628992739e+07, 2.000003372515e+07 },
  quad4 = { 9.533236910099e-04, 6.066618455043e-04 },
}
for _, cell in ipairs({ 'quad8', 'quad4' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/axis_cylinder_' .. cell .. '.med' }
  MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'LEFT' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = { 'BOTTOM', 'TOP' }, DY = 0.0 },
                             PRES_REP = _F{ GROUP_MA = 'LEFT', PRES = P } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
  -- The AXIS stresses (SIXX radial, SIYY axial, SIZZ hoop, SIXY) written to the MED result.
  if cell == 'quad8' then IMPR_RESU{ FORMAT = 'MED', RESU = _F{ RESULTAT = R } } end
  local checks = {}
  local function t(cham, cmp, node, refe, precision)
    local f = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, GROUP_NO = node,
                  REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = precision, LEGENDE = cell }
    -- Zero in theory: both checks on the scale of P (the computed value is discretisation error
    -- plus round-off, and round-off changes with the machine's arithmetic kernels).
    if refe == 0.0 then f.ORDRE_GRANDEUR = P end
    f.VALE_CALC = calc[cell][#checks + 1]
    checks[#checks + 1] = f
  end
  for _, node in ipairs({ 'C00', 'C10' }) do
    local r = node == 'C00' and A or B
    t('DEPL', 'DX', node, ur(r), cell == 'quad8' and 1.0e-9 or 3.0e-5)
    if cell == 'quad8' then
      local precision = node == 'C00' and 1.0e-4 or 2.0e-5
      t('SIGM_NOEU', 'SIXX', node, srr(r), precision)
      t('SIGM_NOEU', 'SIZZ', node, stt(r), precision)
      t('SIGM_NOEU', 'SIYY', node, 2 * NU * K, precision)
    end
  end
  TEST_RESU{ RESU = checks }
end
FIN()
