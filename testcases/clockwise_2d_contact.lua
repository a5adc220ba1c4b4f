-- Clockwise 2D cells are ordinary cells: a two-block contact problem (SSNP121 geometry, upper block
-- 6x6 QUAD4 on a lower block of 4x4x2 TRIA3, non-matching) meshed counter-clockwise, with the lower
-- (master) block clockwise, and with the upper (slave) block clockwise gives the same displacements,
-- stresses and contact pressures. Clockwise blocks have every cell and every boundary edge listed
-- as Gmsh does for a surface built from a clockwise curve loop; each variant is read from MED, Gmsh
-- 2.2 and Gmsh 4.1 files (tools/make_meshes.sh). LIRE_MAILLAGE reorients the clockwise cells;
-- ORIE_PEAU_2D then turns the contact and loaded edges outward.
-- Loading: DY = -0.05 m on CD, DX = 0 on DA, GH clamped, pressure 2e4 Pa on BC and 1e4 Pa on FG
-- (the right sides); E = 2e6 Pa, NU = 0.3, plane strain; slave AB, master EF; CONTINUE (augmented
-- Lagrangian) and DISCRETE (active set). The field is not uniform (clamped base, lateral pressures).
-- Every reading is checked against the same VALE_CALC to 1e-12 (relative); the unit test
-- ClockwiseDecks.ContactSameFieldsEveryOrientationAndFormat compares the full fields.
-- Reference: none; VALE_CALC from a real run. Runtime label: fast, contact.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }

-- VALE_CALC (counter-clockwise MED mesh): DY at O (middle of AB), DX at B, sums of |DX| and |DY|,
-- extreme SIYY of SIGM_NOEU, contact pressure LAGS_C at O, its sum over all nodes, and its minimum.
local calc = {
  CONTINUE = { DY_O = -2.603425520441011e-02, DX_B = 5.387859260792330e-03, SUM_DX = 2.380916744583793e-01,
               SUM_DY = 2.180773826768060e+00, SIYY_MIN = -6.791709925804290e+04, SIYY_MAX = -4.849268059625570e+04,
               LAGS_O = -5.939554474150290e+04, LAGS_SUM = -4.253675254474189e+05, LAGS_MIN = -6.481224098951431e+04 },
  DISCRETE = { DY_O = -2.603425520441009e-02, DX_B = 5.387859260792326e-03, SUM_DX = 2.380916744583795e-01,
               SUM_DY = 2.180773826768059e+00, SIYY_MIN = -6.791709925804296e+04, SIYY_MAX = -4.849268059625582e+04,
               LAGS_O = -5.956233992645994e+04, LAGS_SUM = -4.265118390403347e+05, LAGS_MIN = -6.498626894574035e+04 },
}

local meshes = {}
for _, variant in ipairs({ 'ccw', 'cw_master', 'cw_slave' }) do
  meshes[#meshes + 1] = { variant .. '_med', 'MED', 'meshes/contact2d_' .. variant .. '.med' }
  meshes[#meshes + 1] = { variant .. '_msh22', 'GMSH', 'meshes/contact2d_' .. variant .. '_v22.msh' }
  meshes[#meshes + 1] = { variant .. '_msh41', 'GMSH', 'meshes/contact2d_' .. variant .. '_v41.msh' }
end

-- Results by formulation and reading, for the unit test that compares them field by field.
CONTACT_RESULTS = { CONTINUE = {}, DISCRETE = {} }
for _, m in ipairs(meshes) do
  local label, format, file = m[1], m[2], m[3]
  local MA = LIRE_MAILLAGE{ FORMAT = format, FICHIER = file }
  MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = { 'AB', 'EF', 'BC', 'FG' } } }
  local MO = AFFE_MODELE{ MAILLAGE = MA,
                          AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO,
                             DDL_IMPO = { _F{ GROUP_NO = 'CD', DY = -0.05 }, _F{ GROUP_NO = 'DA', DX = 0.0 },
                                          _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } },
                             PRES_REP = { _F{ GROUP_MA = 'BC', PRES = 2.0e4 }, _F{ GROUP_MA = 'FG', PRES = 1.0e4 } } }
  for _, formulation in ipairs({ 'CONTINUE', 'DISCRETE' }) do
    local CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = formulation,
                               ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF' } }
    local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, CONTACT = CONT,
                             EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                             COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
    CONTACT_RESULTS[formulation][label] = R
    local c = calc[formulation]
    local function t(cham, cmp, value, where)
      local check = { RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, VALE_CALC = value,
                      TOLE_MACHINE = 1.0e-12, LEGENDE = formulation .. ' ' .. label }
      for k, v in pairs(where) do check[k] = v end
      return _F(check)
    end
    TEST_RESU{ RESU = {
      t('DEPL', 'DY', c.DY_O, { GROUP_NO = 'O' }),
      t('DEPL', 'DX', c.DX_B, { GROUP_NO = 'B' }),
      t('DEPL', 'DX', c.SUM_DX, { TYPE_TEST = 'SOMM_ABS' }),
      t('DEPL', 'DY', c.SUM_DY, { TYPE_TEST = 'SOMM_ABS' }),
      t('SIGM_NOEU', 'SIYY', c.SIYY_MIN, { TYPE_TEST = 'MIN' }),
      t('SIGM_NOEU', 'SIYY', c.SIYY_MAX, { TYPE_TEST = 'MAX' }),
      t('DEPL', 'LAGS_C', c.LAGS_O, { GROUP_NO = 'O' }),
      t('DEPL', 'LAGS_C', c.LAGS_SUM, { TYPE_TEST = 'SOMM' }),
      t('DEPL', 'LAGS_C', c.LAGS_MIN, { TYPE_TEST = 'MIN' }),
    } }
  end
end
FIN()
