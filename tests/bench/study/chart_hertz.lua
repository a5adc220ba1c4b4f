-- The Hertz chart: peak contact pressure against cost, over refinement, for each model family
-- and contact method. One row per run in chart_hertz.csv (IMPR_MESURE).
-- err_p0: the peak pressure against Hertz, |p - p(r)| / p0 at the slave node nearest the axis
-- (or O) that carries a pressure, r_peak its distance to the axis (or O): O_BLOCK itself (r = 0)
-- except for AXIS QUAD8 mortar, where the corner node on the axis has no multiplier (its dual
-- weight, the integral of r N over the cell, is zero) and the node is the mid-side at h0/2.
-- Scenes (testcases/hertz_cylinder_dplan.lua, hertz_sphere_axis.lua and hertz_sphere_3d.lua,
-- R = 1 m, E = 1e9 Pa, nu = 0.3 on both bodies, block bottom fixed, pressure on the ball's flat
-- top, the ball held by the contact alone: CONTACT_INIT = 'OUI' for every method):
--   D_PLAN   cylinder on block, line contact, half-width b = 0.02 m; meshes `lunaster-meshgen
--            --hertz quad8:50 --grading 1.1 --refine K` (h0 = b / K)
--   AXIS-U   sphere on block, axisymmetric (x = r), contact radius a = 0.1 m; uniform QUAD8
--            meshes `--hertz quad8:N` (h0 = 1/N)
--   AXIS-G   the same, graded: `--hertz quad8:20 --grading 1.5 --refine K` (h0 = a / (2 K))
--   3D-U     sphere on block, quarter model, contact radius a = 0.1 m; uniform HEXA20 meshes
--            `--hertz hexa20:N` (h0 = 1/N)
--   3D-G     the same, graded: `--hertz hexa20:20 --grading 1.5 --refine K` (h0 = a / (2 K))
-- (run_study.sh makes the meshes: meshes/hertz_<family>_k<K>.med.) Slave = BLOCK_TOP, master =
-- BALL_SURF for every method. p is LAGS_C for MORTAR and CONTINUE, CONT_NOEU PRES for the
-- discrete methods, read over BLOCK_TOP with POST_RELEVE_T.
-- Run: lunaster run chart_hertz.lua --out DIR (config.lua lists the runs: hertz_runs).
local config = require('config')

local R, E, NU = 1.0, 1.0e9, 0.3
local E_STAR = 1.0 / (2.0 * (1.0 - NU ^ 2) / E)

--- Scene of a family: modelisation, symmetry conditions, the load Q and the exact p0.
local function scene(family)
  if family == 'D_PLAN' then
    local b = 0.02
    local p = math.pi * E_STAR * b ^ 2 / (4.0 * R)  -- force per unit length giving the half-width b
    return { modelisation = 'D_PLAN', q = p / (2.0 * R), p0 = 2.0 * p / (math.pi * b), size = b,
             ddl = { _F{ GROUP_MA = { 'AXIS_BALL', 'AXIS_BLOCK' }, DX = 0.0 },
                     _F{ GROUP_MA = 'BLOCK_BOTTOM', DX = 0.0, DY = 0.0 } } }
  end
  local a = 0.1
  local f = 4.0 * E_STAR * a ^ 3 / (3.0 * R)  -- force on the whole sphere giving the contact radius a
  local p0 = 3.0 * f / (2.0 * math.pi * a ^ 2)
  if family:sub(1, 4) == 'AXIS' then
    return { modelisation = 'AXIS', q = f / (math.pi * R ^ 2), p0 = p0, size = a,
             ddl = { _F{ GROUP_MA = { 'AXIS_BALL', 'AXIS_BLOCK' }, DX = 0.0 },
                     _F{ GROUP_MA = 'BLOCK_BOTTOM', DX = 0.0, DY = 0.0 } } }
  end
  return { modelisation = '3D', q = f / (math.pi * R ^ 2), p0 = p0, size = a,
           ddl = { _F{ GROUP_MA = { 'SYMX_BALL', 'SYMX_BLOCK' }, DX = 0.0 },
                   _F{ GROUP_MA = { 'SYMY_BALL', 'SYMY_BLOCK' }, DY = 0.0 },
                   _F{ GROUP_MA = 'BLOCK_BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 } } }
end

local METHODS = {
  { name = 'MORTAR', kind = 'MORTAR' },
  { name = 'CONTINUE', kind = 'CONTINUE' },
  { name = 'CONTRAINTE', kind = 'CONTRAINTE' },
  { name = 'MORTAR-PEN-1e13', kind = 'MORTAR', algo = 'PENALISATION', coef = 1.0e13 },
  { name = 'PENALISATION-1e13', kind = 'PENALISATION', e_n = 1.0e13 },
}

local times = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

local function solve(mesh_file, m, sc)
  local ma = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = mesh_file }
  local mo = AFFE_MODELE{ MAILLAGE = ma, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = sc.modelisation } }
  local mat = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
  local cm = AFFE_MATERIAU{ MAILLAGE = ma, AFFE = _F{ TOUT = 'OUI', MATER = mat } }
  local cha = AFFE_CHAR_MECA{ MODELE = mo, DDL_IMPO = sc.ddl, PRES_REP = _F{ GROUP_MA = 'BALL_TOP', PRES = sc.q } }
  local excit = { _F{ CHARGE = cha } }
  local snl = { MODELE = mo, CHAM_MATER = cm, EXCIT = excit, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                INCREMENT = _F{ LIST_INST = times }, CONVERGENCE = _F{ ITER_GLOB_MAXI = 40 } }
  if m.kind == 'MORTAR' then
    local zone = { APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'BLOCK_TOP', GROUP_MA_MAIT = 'BALL_SURF',
                   CONTACT_INIT = 'OUI', ALGO_CONT = m.algo or 'LAGRANGIEN' }
    if m.coef then zone.COEF_CONT = m.coef end
    snl.CONTACT = DEFI_CONT{ MODELE = mo, REAC_GEOM = 'SANS', ZONE = _F(zone) }
  elseif m.kind == 'CONTINUE' then
    snl.CONTACT = DEFI_CONTACT{ MODELE = mo, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE',
                                ALGO_RESO_GEOM = 'POINT_FIXE', REAC_GEOM = 'SANS',
                                ZONE = _F{ GROUP_MA_ESCL = 'BLOCK_TOP', GROUP_MA_MAIT = 'BALL_SURF', CONTACT_INIT = 'OUI',
                                           COEF_CONT = E } }
  else
    local c = { METHODE = m.kind, GROUP_MA_ESCL = 'BLOCK_TOP', GROUP_MA_MAIT = 'BALL_SURF', CONTACT_INIT = 'OUI',
                REAC_GEOM = 'SANS' }
    if m.e_n then c.E_N = m.e_n end
    excit[#excit + 1] = _F{ CHARGE = AFFE_CHAR_MECA{ MODELE = mo, CONTACT = _F(c) } }
  end
  return STAT_NON_LINE(snl)
end

--- (r, p) at the slave node nearest the axis (or O) that carries a pressure (BLOCK_TOP rows of
--- the field whose component is filled), r = distance to the axis (2D) or to O (3D).
local function peak(r, cham, cmp)
  local t = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'P', RESULTAT = r, NOM_CHAM = cham,
                                        GROUP_NO = 'BLOCK_TOP', NOM_CMP = cmp, NUME_ORDRE = 1 } }
  local best_r, best_p
  for i = 1, #t[cmp] do
    local ok, p = pcall(function() return t[cmp][i] end)
    if ok and p ~= nil then
      local x = t['COOR_X'][i]
      local y = t['COOR_Y'][i]  -- 0 on BLOCK_TOP in 2D (y is the axis there)
      local rr = math.sqrt(x * x + y * y)
      if best_r == nil or rr < best_r then best_r, best_p = rr, p end
    end
  end
  return best_r, best_p
end

local function run(family, k, m)
  local sc = scene(family)
  local mesh_file = 'meshes/hertz_' .. family:lower():gsub('[^%w]', '') .. '_k' .. k .. '.med'
  local para = { 'family', 'method', 'k', 'status', 'err_p0', 'r_peak' }
  local vale = { family, m.name, tostring(k) }
  local cham, cmp = 'DEPL', 'LAGS_C'
  if m.kind ~= 'MORTAR' and m.kind ~= 'CONTINUE' then cham, cmp = 'CONT_NOEU', 'PRES' end
  local ok, r = pcall(solve, mesh_file, m, sc)
  local rr, p
  if ok then ok, rr, p = pcall(peak, r, cham, cmp) end
  if ok and rr == nil then ok, rr = false, 'no slave node carries ' .. cmp end
  if ok then
    local exact = sc.p0 * math.sqrt(math.max(1.0 - (rr / sc.size) ^ 2, 0.0))
    vale[4], vale[5], vale[6] = 'ok', string.format('%.6g', math.abs(-p - exact) / sc.p0), string.format('%.6g', rr)
    IMPR_MESURE{ FICHIER = 'chart_hertz.csv', RESULTAT = r, PARA = para, VALE_K = vale }
  else
    local message = tostring(rr or r):gsub('\n.*', '')
    print('study: ' .. mesh_file .. ' ' .. m.name .. ' failed: ' .. message)
    vale[4], vale[5], vale[6] = 'failed: ' .. message, '', ''
    IMPR_MESURE{ FICHIER = 'chart_hertz.csv', PARA = para, VALE_K = vale }
  end
end

DEBUT()
for _, fk in ipairs(config.hertz_runs) do
  local family, k, methods = fk[1], fk[2], fk[3]
  for _, m in ipairs(METHODS) do
    if methods == nil or methods[m.name] then run(family, k, m) end
  end
end
FIN()
