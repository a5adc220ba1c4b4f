-- SOLVEUR METHODE='MUMPS' and 'PETSC' on models without contact: serially one process solves; under
-- `mpirun -np N` the model is shared among the ranks (Scotch partition of the cells, each rank
-- assembling the stiffness of its own nodes, MUMPS given each rank's entries, PETSc each rank's
-- rows), and the values must equal the serial ones (tests/mpi compares them, rank by rank output).
--   1. SSNP121 I's geometry glued (meshes/glued3d_*.med: two unit cubes stacked, HEXA8 and HEXA20),
--      ENCAST clamped, SURCHA moved by DZ = -0.1, E = 2e6, NU = 0: SIZZ = -1e5 Pa everywhere and
--      DZ = -0.05 m on the interface, to 1e-8 with MUMPS and with PETSc (CG + BOOMER, CG + GAMG,
--      FGMRES + LDLT_SP) at RESI_RELA = 1e-12; the reactions on ENCAST sum to 1e5 N (the unit
--      face's). Under mpirun, CALC_CHAMP computes each cell on the rank that held it and the ranks
--      sum their parts.
--   2. The thick-walled cylinder of axis_thick_cylinder.lua (AXIS QUAD8, Lame solution) with MUMPS:
--      u_r at the inner and outer radius to 1e-4 (the mesh's own error, as in that deck).
--      Under mpirun, the pressure is computed by the rank owning each face's first node and the
--      ranks sum their parts.
--   3. Contact with MUMPS: SSNP121 A (ssnp121a.lua: CONTINUE, contact multipliers, a saddle
--      point) at code_aster's 1 %, and SSNP121 I with mortar contact (ssnp121i_mortar.lua: the
--      active slave displacements eliminated) at 1e-8. Under mpirun the ranks share the pairing
--      (each projects a block of the points, or integrates the mortar overlaps of a block of
--      slave cells, and they exchange the results) and each keeps the contact terms of its own
--      columns.
-- Reference: analytical. VALE_CALC: lunaster's own values from a real run (non-regression).
-- Runtime label: fast, 3D, solver.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
-- VALE_CALC: lunaster's own values from a real serial run (non-regression, relative 1e-6), in the
-- order of the checks below.
local calc = {
  ['hexa8 MUMPS'] = { -1.000000000000e+05, -1.000000000000e+05, -5.000000000000e-02, -5.000000000000e-02, 1.000000000000e+05 },
  ['hexa8 CG_BOOMER'] = { -1.000000000000e+05, -9.999999999996e+04, -5.000000000001e-02, -4.999999999999e-02, 9.999999999999e+04 },
  ['hexa8 CG_GAMG'] = { -1.000000000000e+05, -1.000000000000e+05, -5.000000000000e-02, -5.000000000000e-02, 1.000000000000e+05 },
  ['hexa8 FGMRES_LDLT_SP'] = { -1.000000000000e+05, -9.999999999996e+04, -5.000000000000e-02, -4.999999999999e-02, 9.999999999998e+04 },
  ['hexa20 MUMPS'] = { -1.000000000000e+05, -1.000000000000e+05, -5.000000000000e-02, -5.000000000000e-02, 1.000000000000e+05 },
  ['hexa20 CG_BOOMER'] = { -1.000000000003e+05, -9.999999999947e+04, -5.000000000003e-02, -4.999999999997e-02, 9.999999999994e+04 },
  ['hexa20 CG_GAMG'] = { -1.000000000007e+05, -9.999999999933e+04, -5.000000000010e-02, -4.999999999993e-02, 1.000000000000e+05 },
  ['hexa20 FGMRES_LDLT_SP'] = { -1.000000000003e+05, -9.999999999977e+04, -4.999999999998e-02, -4.999999999991e-02, 9.999999999987e+04 },
  ['ssnp121i mortar MUMPS'] = { -1.000000000000e+05, -9.999999999999e+04, -5.000000000000e-02, -5.000000000000e-02 },
  ['axis quad8 MUMPS'] = { 9.533333331379e-04, 6.066666665685e-04 },
}
local solvers = {
  MUMPS = _F{ METHODE = 'MUMPS' },
  CG_BOOMER = _F{ METHODE = 'PETSC', ALGORITHME = 'CG', PRE_COND = 'BOOMER', RESI_RELA = 1.0e-12 },
  CG_GAMG = _F{ METHODE = 'PETSC', ALGORITHME = 'CG', PRE_COND = 'GAMG', RESI_RELA = 1.0e-12 },
  FGMRES_LDLT_SP = _F{ METHODE = 'PETSC', ALGORITHME = 'FGMRES', PRE_COND = 'LDLT_SP', RESI_RELA = 1.0e-12 },
}
for _, cell in ipairs({ 'hexa8', 'hexa20' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/glued3d_' .. cell .. '.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO,
                             DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                          _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
  for _, name in ipairs({ 'MUMPS', 'CG_BOOMER', 'CG_GAMG', 'FGMRES_LDLT_SP' }) do
    local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, SOLVEUR = solvers[name],
                             COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' }, FORCE = { 'REAC_NODA' } }
    local label, k = cell .. ' ' .. name, 0
    local function t(cham, cmp, kind, refe, group)
      k = k + 1
      return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = group,
                 REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-8, LEGENDE = label,
                 VALE_CALC = calc[label][k] }
    end
    TEST_RESU{ RESU = {
      t('SIGM_NOEU', 'SIZZ', 'MIN', -1.0e5), t('SIGM_NOEU', 'SIZZ', 'MAX', -1.0e5),
      t('DEPL', 'DZ', 'MIN', -0.05, 'SURESC'), t('DEPL', 'DZ', 'MAX', -0.05, 'SURESC'),
      t('REAC_NODA', 'DZ', 'SOMM', 1.0e5, 'ENCAST'),
    } }
  end
end

-- 2. Thick-walled cylinder, AXIS QUAD8, MUMPS.
local E, NU, P, A, B = 2.0e11, 0.3, 1.0e8, 1.0, 2.0
local LAMBDA, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
local K = P * A * A / (B * B - A * A)
local function ur(r) return K / (2 * (LAMBDA + MU)) * r + K * B * B / (2 * MU) / r end
local STEEL = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/axis_cylinder_quad8.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'LEFT' } }
local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = STEEL } }
local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = { 'BOTTOM', 'TOP' }, DY = 0.0 },
                           PRES_REP = _F{ GROUP_MA = 'LEFT', PRES = P } }
local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, SOLVEUR = _F{ METHODE = 'MUMPS' },
                         COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
-- Under mpirun, rank 0 writes it: the same file as a serial run's (tests/mpi compares them).
IMPR_RESU{ FORMAT = 'MED', RESU = _F{ RESULTAT = R } }
TEST_RESU{ RESU = {
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', GROUP_NO = 'C00', REFERENCE = 'ANALYTIQUE',
      VALE_REFE = ur(A), PRECISION = 1.0e-4, LEGENDE = 'axis quad8 MUMPS', VALE_CALC = calc['axis quad8 MUMPS'][1] },
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', GROUP_NO = 'C10', REFERENCE = 'ANALYTIQUE',
      VALE_REFE = ur(B), PRECISION = 1.0e-4, LEGENDE = 'axis quad8 MUMPS', VALE_CALC = calc['axis quad8 MUMPS'][2] },
} }

-- 3. Contact, MUMPS. SSNP121 A: CONTINUE with multipliers (VALE_CALC: ssnp121a.lua's, same scene).
local RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                       _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
  local CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE',
                             ALGO_RESO_GEOM = 'POINT_FIXE', REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
                             ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON',
                                        ORDRE_INT = 4, COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, CONTACT = CONT, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                           CONVERGENCE = _F{ RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 },
                           SOLVEUR = _F{ METHODE = 'MUMPS' } }
  local calc_a = {
    A = { DY = -4.999669690478e-02, LAGS_C = -1.000795227287e+05 },
    O = { DY = -4.997830886910e-02, LAGS_C = -1.003593668221e+05 },
    B = { DY = -4.999669690478e-02, LAGS_C = -1.000795227287e+05 },
  }
  local checks = {}
  for _, point in ipairs({ 'A', 'O', 'B' }) do
    for _, cmp in ipairs({ 'DY', 'LAGS_C' }) do
      checks[#checks + 1] = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = cmp,
                                VALE_CALC = calc_a[point][cmp], REFERENCE = 'ANALYTIQUE',
                                VALE_REFE = cmp == 'DY' and -0.05 or -1.0e5, PRECISION = 1.0e-2,
                                LEGENDE = 'ssnp121a MUMPS' }
    end
  end
  TEST_RESU{ RESU = checks }
end

-- SSNP121 I, mortar: exact to round-off.
do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121i.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                                       _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
  local CONT = DEFI_CONT{ MODELE = MO, ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURESC',
                                                 GROUP_MA_MAIT = 'SURMAI', ALGO_CONT = 'LAGRANGIEN',
                                                 CONTACT_INIT = 'INTERPENETRE' } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, CONTACT = CONT, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                           SOLVEUR = _F{ METHODE = 'MUMPS' } }
  local function t(cmp, kind, refe, k)
    return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = 'SURESC',
               REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-8, LEGENDE = 'ssnp121i mortar MUMPS',
               VALE_CALC = calc['ssnp121i mortar MUMPS'][k] }
  end
  TEST_RESU{ RESU = { t('LAGS_C', 'MIN', -1.0e5, 1), t('LAGS_C', 'MAX', -1.0e5, 2), t('DZ', 'MIN', -0.05, 3),
                      t('DZ', 'MAX', -0.05, 4) } }
end
FIN()
