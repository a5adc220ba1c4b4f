-- A unit cube (one HEXA8, 3D) in uniaxial tension past yield, then unloaded, with von Mises
-- plasticity: RELATION = 'VMIS_ISOT_LINE' (ECRO_LINE) and, on a second run, 'VMIS_ISOT_TRAC'
-- (a TRACTION curve with PROL_DROITE = 'LINEAIRE', loaded past its last point); then one QUAD4 in
-- plane stress (C_PLAN) along the first history, RESI_INTE_RELA and ITER_INTE_MAXI given.
-- Purpose: STAT_NON_LINE COMPORTEMENT builds the von Mises law from each cell's DEFI_MATERIAU and
--          drives it through Newton: stresses (SIEF_ELGA), the cumulated plastic strain (VARI_ELGA
--          V1) and the indicator of the step (V2) at loaded, yielding and unloaded instants.
-- Problem: u_x = 0 on LEFT, u_y = 0 on FRONT, u_z = 0 on BOTTOM, u_z = eps(t) on TOP (side 1):
--          a homogeneous uniaxial stress SIZZ, every Gauss point in the same state (in C_PLAN: SIYY,
--          u_y = eps(t) on TOP, DX on RIGHT the lateral strain likewise).
-- Reference: analytical, uniaxial closed form. With the curve sigma = f(eps) on loading (ECRO_LINE:
--          f = E eps below SY / E, SY + ET (eps - SY / E) above; TRACTION: the curve, its slope
--          extended past the last point), eps_max the largest strain so far:
--            SIZZ = f(eps_max) - E (eps_max - eps)  (elastic unloading, no reverse yield here),
--            V1 = p = eps_max - f(eps_max) / E  (0 while elastic),
--            DX on RIGHT = eps_xx = -NU SIZZ / E - p / 2  (plastic flow is isochoric).
--          The radial return is exact for a uniaxial state and the bilinear cell holds the
--          homogeneous field, so the discrete solution is the closed form up to rounding: PRECISION
--          1e-10 (CONVERGENCE RESI_GLOB_RELA = 1e-12, so that Newton's last iterate is exact too).
-- VALE_CALC: lunaster's values from a real run (non-regression).  Units: MPa, mm. Runtime: fast.
DEBUT()
local E, NU, SY, ET = 2.0e5, 0.3, 200.0, 2000.0
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/unit_hexa8.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'FRONT', DY = 0.0 },
                                               _F{ GROUP_NO = 'BOTTOM', DZ = 0.0 }, _F{ GROUP_NO = 'TOP', DZ = 1.0 } } }
-- The same uniaxial stress in plane stress (one QUAD4, C_PLAN, SIYY along y): the law's local
-- iteration on the zz strain, its tolerance and iteration limit given by RESI_INTE_RELA and
-- ITER_INTE_MAXI.
MA2 = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/unit_quad4.med' }
MO2 = AFFE_MODELE{ MAILLAGE = MA2, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN' } }
CH2 = AFFE_CHAR_MECA{ MODELE = MO2, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                                 _F{ GROUP_NO = 'TOP', DY = 1.0 } } }

-- The uniaxial answer at strain eps, eps_max the largest so far, for the loading curve f:
-- SIZZ, p and the lateral strain.
local function closed_form(f, eps, eps_max)
  local sig_max = f(eps_max)
  local p = math.max(0.0, eps_max - sig_max / E)
  local sig = sig_max - E * (eps_max - eps)
  return sig, p, -NU * sig / E - p / 2.0
end

-- `variant`: nil, or 'meca' (MECA_NON_LINE, code_aster 17's spelling, with the integration
-- options at the law's own values) or 'comp_elas' (STAT_NON_LINE's older COMP_ELAS); the same
-- solve whatever the spelling.
local function run(material, relation, strains, f, calc, plane, variant)
  local times = {}
  local vale = {}
  for i, eps in ipairs(strains) do
    times[i] = i - 1.0
    vale[#vale + 1] = i - 1.0
    vale[#vale + 1] = eps
  end
  local EPS = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = vale }
  local L = DEFI_LIST_REEL{ VALE = times }
  local mesh, model, load, axial = MA, MO, CH, 'SIZZ'
  local behaviour = _F{ RELATION = relation, TOUT = 'OUI', DEFORMATION = 'PETIT' }
  if plane then
    mesh, model, load, axial = MA2, MO2, CH2, 'SIYY'
    behaviour = _F{ RELATION = relation, TOUT = 'OUI', RESI_INTE_RELA = 1.0e-13, ITER_INTE_MAXI = 20 }
  end
  local CM = AFFE_MATERIAU{ MAILLAGE = mesh, AFFE = _F{ TOUT = 'OUI', MATER = material } }
  local solve = { MODELE = model, CHAM_MATER = CM, EXCIT = _F{ CHARGE = load, FONC_MULT = EPS },
                  CONVERGENCE = _F{ RESI_GLOB_RELA = 1.0e-12 }, INCREMENT = _F{ LIST_INST = L } }
  local R
  if variant == 'meca' then
    behaviour = _F{ RELATION = relation, TOUT = 'OUI', RESI_INTE_RELA = 1.0e-12, ITER_INTE_MAXI = 100 }
    solve.COMPORTEMENT = behaviour
    R = MECA_NON_LINE(solve)
  else
    solve[variant == 'comp_elas' and 'COMP_ELAS' or 'COMPORTEMENT'] = behaviour
    R = STAT_NON_LINE(solve)
  end
  local checks = {}
  local eps_max = 0.0
  for i, eps in ipairs(strains) do
    if i > 1 then
      local yielding = eps > eps_max and eps > SY / E
      eps_max = math.max(eps_max, eps)
      local sig, p, exx = closed_form(f, eps, eps_max)
      local t = times[i]
      local c = calc[i - 1]
      local SIEF = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'ELGA_SIEF_R', RESULTAT = R, NOM_CHAM = 'SIEF_ELGA',
                               INST = t }
      local VARI = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'ELGA_VARI_R', RESULTAT = R, NOM_CHAM = 'VARI_ELGA',
                               INST = t }
      local cells = {}
      local function check(field, cmp, kind, refe, value)
        cells[#cells + 1] = _F{ CHAM_GD = field, NOM_CMP = cmp, TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE',
                                VALE_REFE = refe, VALE_CALC = value, PRECISION = 1.0e-10 }
      end
      for _, kind in ipairs({ 'MIN', 'MAX' }) do
        check(SIEF, axial, kind, sig, c[1])
        check(VARI, 'V1', kind, p, c[2])
        check(VARI, 'V2', kind, yielding and 1.0 or 0.0, yielding and 1.0 or 0.0)
        checks[#checks + 1] = _F{ RESULTAT = R, INST = t, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', TYPE_TEST = kind,
                                  GROUP_NO = 'RIGHT', REFERENCE = 'ANALYTIQUE', VALE_REFE = exx, VALE_CALC = c[3],
                                  PRECISION = 1.0e-10 }
      end
      TEST_RESU{ CHAM_ELEM = cells }
    end
  end
  TEST_RESU{ RESU = checks }
end

-- Linear hardening: elastic, yield, further loading, unloading into compression (elastic: -s3 / 2
-- is above the reverse yield stress -s3), reloading (elastic).
local function f_line(eps) return eps <= SY / E and E * eps or SY + ET * (eps - SY / E) end
local s3 = f_line(0.01)
MAT_L = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU }, ECRO_LINE = _F{ D_SIGM_EPSI = ET, SY = SY } }
local HISTORY_L = { 0.0, 0.5 * SY / E, 0.003, 0.01, 0.01 - 1.5 * s3 / E, 0.0095 }
-- Both runs of this history (3D and C_PLAN) gave these values to the printed digits.
local CALC_L = {
  [1] = { 1.000000000e+02, 0.000000000e+00, -1.500000000e-04 },
  [2] = { 2.040000000e+02, 1.980000000e-03, -1.296000000e-03 },
  [3] = { 2.180000000e+02, 8.910000000e-03, -4.782000000e-03 },
  [4] = { -1.090000000e+02, 8.910000000e-03, -4.291500000e-03 },
  [5] = { 1.180000000e+02, 8.910000000e-03, -4.632000000e-03 },
}
run(MAT_L, 'VMIS_ISOT_LINE', HISTORY_L, f_line, CALC_L)

-- A traction curve (E = SY / eps_1 from its first point), loaded on its second segment, unloaded,
-- then reloaded past its last point (PROL_DROITE = 'LINEAIRE': the last slope goes on); solved by
-- MECA_NON_LINE.
local EPS_T = { SY / E, 0.005, 0.015 }
local SIG_T = { SY, 230.0, 250.0 }
local function f_trac(eps)
  if eps <= EPS_T[1] then return E * eps end
  for k = 1, #EPS_T - 1 do
    if eps <= EPS_T[k + 1] then
      return SIG_T[k] + (SIG_T[k + 1] - SIG_T[k]) / (EPS_T[k + 1] - EPS_T[k]) * (eps - EPS_T[k])
    end
  end
  local n = #EPS_T
  return SIG_T[n] + (SIG_T[n] - SIG_T[n - 1]) / (EPS_T[n] - EPS_T[n - 1]) * (eps - EPS_T[n])
end
CURVE = DEFI_FONCTION{ NOM_PARA = 'EPSI', PROL_DROITE = 'LINEAIRE',
                       VALE = { EPS_T[1], SIG_T[1], EPS_T[2], SIG_T[2], EPS_T[3], SIG_T[3] } }
MAT_T = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU }, TRACTION = _F{ SIGM = CURVE } }
run(MAT_T, 'VMIS_ISOT_TRAC', { 0.0, 0.012, 0.010, 0.02 },
    f_trac, {
      [1] = { 2.440000000e+02, 1.078000000e-02, -5.756000000e-03 },
      [2] = { -1.560000000e+02, 1.078000000e-02, -5.156000000e-03 },
      [3] = { 2.600000000e+02, 1.870000000e-02, -9.740000000e-03 },
    }, false, 'meca')
-- Plane stress, linear hardening: the first history (STAT_NON_LINE's COMP_ELAS spelling).
run(MAT_L, 'VMIS_ISOT_LINE', HISTORY_L, f_line, CALC_L, true, 'comp_elas')
FIN()
