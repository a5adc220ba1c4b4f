-- Clockwise 2D cells are ordinary cells: a pressure-loaded block meshed counter-clockwise and
-- clockwise gives the same results. Unit square (distorted 3x3 QUAD8 and TRIA6 blocks), BOTTOM
-- clamped, pressure 1e4 Pa on TOP and 4e3 Pa on RIGHT (after ORIE_PEAU_2D), plane strain.
-- Each block is read six times: counter-clockwise and clockwise (every cell, and every boundary
-- edge, listed as Gmsh does for a surface built from a clockwise curve loop), from MED, Gmsh 2.2
-- and Gmsh 4.1 files (tools/make_meshes.sh). LIRE_MAILLAGE reorients the clockwise cells and
-- says so; ORIE_PEAU_2D then turns the edges outward, so that both pressures push into the body.
-- Every reading is checked against the same VALE_CALC to 1e-12 (relative); the unit test
-- ClockwiseDecks.PressureBlockSameFieldsEveryOrientationAndFormat compares the full fields.
-- Reference: none (the field is not uniform); VALE_CALC from a real run. Runtime label: fast.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- VALE_CALC (counter-clockwise MED mesh): DY at the corner C11 and C01, DX at C11, sums of |DX|
-- and |DY| over all nodes, and the extreme SIYY / SIXX of SIGM_NOEU.
local calc = {
  quad8 = { DY_C11 = -1.929303950957009e-03, DY_C01 = -6.286901721297006e-03, DX_C11 = -5.517302972654157e-03,
            SUM_DX = 1.222731078753046e-01, SUM_DY = 8.330319183743859e-02,
            SIYY_MIN = -2.656047805302442e+04, SIYY_MAX = 3.829634289746268e+03, SIXX_MIN = -1.004384056741927e+04 },
  tria6 = { DY_C11 = -1.901944977908058e-03, DY_C01 = -6.310049005769746e-03, DX_C11 = -5.556394695663999e-03,
            SUM_DX = 1.502215706607147e-01, SUM_DY = 1.021360473495995e-01,
            SIYY_MIN = -2.345389309476816e+04, SIYY_MAX = 4.541139272885076e+03, SIXX_MIN = -6.827183091532341e+03 },
}

local meshes = {
  { 'ccw_med', 'MED', 'meshes/patch_%s.med' },
  { 'cw_med', 'MED', 'meshes/patch_%s_cw.med' },
  { 'ccw_msh22', 'GMSH', 'meshes/patch_%s_v22.msh' },
  { 'cw_msh22', 'GMSH', 'meshes/patch_%s_cw_v22.msh' },
  { 'ccw_msh41', 'GMSH', 'meshes/patch_%s_v41.msh' },
  { 'cw_msh41', 'GMSH', 'meshes/patch_%s_cw_v41.msh' },
}

-- Results by cell type and reading, for the unit test that compares them field by field.
PRESSURE_RESULTS = {}
for _, cell in ipairs({ 'quad8', 'tria6' }) do
  PRESSURE_RESULTS[cell] = {}
  for _, m in ipairs(meshes) do
    local label, format, file = m[1], m[2], string.format(m[3], cell)
    local MA = LIRE_MAILLAGE{ FORMAT = format, FICHIER = file }
    MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = { 'TOP', 'RIGHT' } } }
    local MO = AFFE_MODELE{ MAILLAGE = MA,
                            AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
    local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = 'BLOCK', MATER = MAT } }
    local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                               PRES_REP = { _F{ GROUP_MA = 'TOP', PRES = 1.0e4 },
                                            _F{ GROUP_MA = 'RIGHT', PRES = 4.0e3 } } }
    local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                             COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
    PRESSURE_RESULTS[cell][label] = R
    local c = calc[cell]
    local function t(cham, cmp, value, where)
      local check = { RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, VALE_CALC = value,
                      TOLE_MACHINE = 1.0e-12, LEGENDE = cell .. ' ' .. label }
      for k, v in pairs(where) do check[k] = v end
      return _F(check)
    end
    TEST_RESU{ RESU = {
      t('DEPL', 'DY', c.DY_C11, { GROUP_NO = 'C11' }),
      t('DEPL', 'DY', c.DY_C01, { GROUP_NO = 'C01' }),
      t('DEPL', 'DX', c.DX_C11, { GROUP_NO = 'C11' }),
      t('DEPL', 'DX', c.SUM_DX, { TYPE_TEST = 'SOMM_ABS' }),
      t('DEPL', 'DY', c.SUM_DY, { TYPE_TEST = 'SOMM_ABS' }),
      t('SIGM_NOEU', 'SIYY', c.SIYY_MIN, { TYPE_TEST = 'MIN' }),
      t('SIGM_NOEU', 'SIYY', c.SIYY_MAX, { TYPE_TEST = 'MAX' }),
      t('SIGM_NOEU', 'SIXX', c.SIXX_MIN, { TYPE_TEST = 'MIN' }),
    } }
  end
end
FIN()
