-- One HEXA8 (the unit cube) stretched to s = 1.1 in uniaxial stress under large rotations:
-- STAT_NON_LINE COMPORTEMENT RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP' (Saint-Venant-Kirchhoff
-- on the Green-Lagrange strain, total Lagrangian, as code_aster).
-- Purpose: GROT_GDEP end to end from the deck: the kinematics on the occurrence's cells, Newton
--          through the geometric stiffness, SIEF_ELGA stored per instant as the Cauchy stress.
-- Problem: u_x = 0 on LEFT, u_y = 0 on FRONT, u_z = 0 on BOTTOM, u_z = (s - 1) t on TOP (side 1),
--          t = 0.5, 1: F = diag(a, a, s_t) with s_t = 1 + 0.1 t, homogeneous, every Gauss point alike.
-- Reference: analytical. Green-Lagrange E_zz = (s^2 - 1) / 2; the second Piola-Kirchhoff stress
--          S = lambda tr(E) I + 2 mu E uniaxial (S_xx = S_yy = 0) gives E_xx = E_yy = -NU E_zz, so
--          a^2 = 1 - 2 NU E_zz and S_zz = E E_zz; Cauchy F S F^T / det F:
--            SIZZ = s S_zz / a^2, the other components 0, DX on RIGHT = a - 1.
--          (SSNV121's uniaxial strain stretch, its every unknown imposed, is not this deck: the
--          driver does not yet solve a system with no free unknown.) The trilinear cell holds the
--          homogeneous field exactly: PRECISION 1e-10 (RESI_GLOB_RELA = 1e-12).
-- VALE_CALC: lunaster's values from a real run (non-regression).  Units: MPa, mm. Runtime: fast.
-- The report of the solve's time and counts (code_aster's MESURE_TEMPS; times vary, never checked).
DEBUT{ MESURE_TEMPS = _F{ NIVE_DETAIL = 2, MOYENNE = 'NON' } }
local E, NU = 2.0e5, 0.3
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/unit_hexa8.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'FRONT', DY = 0.0 },
                                               _F{ GROUP_NO = 'BOTTOM', DZ = 0.0 }, _F{ GROUP_NO = 'TOP', DZ = 0.1 } } }
RAMP = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 0.5, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMP },
                   COMPORTEMENT = _F{ RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP', TOUT = 'OUI' },
                   CONVERGENCE = _F{ RESI_GLOB_RELA = 1.0e-12 }, INCREMENT = _F{ LIST_INST = L } }

-- Per instant: lunaster's SIZZ and DX on RIGHT from a real run.
local CALC = {
  [0.5] = { 1.110394635e+04, -1.549504826e-02 },
  [1.0] = { 2.465314835e+04, -3.201239677e-02 },
}
local checks = {}
for _, t in ipairs({ 0.5, 1.0 }) do
  local s = 1.0 + 0.1 * t
  local ezz = (s * s - 1.0) / 2.0
  local a = math.sqrt(1.0 - 2.0 * NU * ezz)
  local szz = s * E * ezz / (a * a)
  SIEF = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'ELGA_SIEF_R', RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', INST = t }
  local cells = {}
  for _, kind in ipairs({ 'MIN', 'MAX' }) do
    for _, c in ipairs({ { 'SIZZ', szz, CALC[t][1] }, { 'SIXX', 0.0, 0.0 }, { 'SIYY', 0.0, 0.0 },
                         { 'SIXY', 0.0, 0.0 }, { 'SIYZ', 0.0, 0.0 }, { 'SIXZ', 0.0, 0.0 } }) do
      local zero = c[2] == 0.0
      cells[#cells + 1] = _F{ CHAM_GD = SIEF, NOM_CMP = c[1], TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE',
                              VALE_REFE = c[2], VALE_CALC = c[3], PRECISION = zero and 1.0e-10 * szz or 1.0e-10,
                              CRITERE = zero and 'ABSOLU' or 'RELATIF' }
    end
  end
  TEST_RESU{ CHAM_ELEM = cells }
  for _, kind in ipairs({ 'MIN', 'MAX' }) do
    checks[#checks + 1] = _F{ RESULTAT = R, INST = t, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', TYPE_TEST = kind,
                              GROUP_NO = 'RIGHT', REFERENCE = 'ANALYTIQUE', VALE_REFE = a - 1.0,
                              VALE_CALC = CALC[t][2], PRECISION = 1.0e-10 }
  end
end
TEST_RESU{ RESU = checks }
FIN()
