-- The Hertz chart: peak contact pressure against cost, over refinement, for each model family
-- and contact method. One row per run in chart_hertz.csv (IMPR_MESURE; err_p0 = |p(O) - p0| / p0).
-- Scenes (testcases/hertz_cylinder_dplan.lua and hertz_sphere_3d.lua, R = 1 m, E = 1e9 Pa,
-- nu = 0.3 on both bodies, block bottom fixed, pressure on the ball's flat top, the ball held by
-- the contact alone: CONTACT_INIT = 'OUI' for every method):
--   D_PLAN   cylinder on block, line contact, half-width b = 0.02 m; meshes `lunaster-meshgen
--            --hertz quad8:50 --grading 1.1 --refine K` (h0 = b / K)
--   3D-U     sphere on block, quarter model, contact radius a = 0.1 m; uniform HEXA20 meshes
--            `--hertz hexa20:N` (h0 = 1/N)
--   3D-G     the same, graded: `--hertz hexa20:20 --grading 1.5 --refine K` (h0 = a / (2 K))
-- (run_study.sh makes the meshes: meshes/hertz_<family>_k<K>.med.) Slave = BLOCK_TOP, master =
-- BALL_SURF for every method. p(O) is LAGS_C for MORTAR and CONTINUE, CONT_NOEU PRES for the
-- discrete methods, at the node O_BLOCK.
-- Run: lunaster run chart_hertz.lua --out DIR (config.lua lists the runs: hertz_runs).
local config = require('config')

local R, E, NU = 1.0, 1.0e9, 0.3
local E_STAR = 1.0 / (2.0 * (1.0 - NU ^ 2) / E)

--- Scene of a family: modelisation, symmetry conditions, the load Q and the exact p0.
local function scene(family)
  if family == 'D_PLAN' then
    local b = 0.02
    local p = math.pi * E_STAR * b ^ 2 / (4.0 * R)  -- force per unit length giving the half-width b
    return { modelisation = 'D_PLAN', q = p / (2.0 * R), p0 = 2.0 * p / (math.pi * b),
             ddl = { _F{ GROUP_MA = { 'AXIS_BALL', 'AXIS_BLOCK' }, DX = 0.0 },
                     _F{ GROUP_MA = 'BLOCK_BOTTOM', DX = 0.0, DY = 0.0 } } }
  end
  local a = 0.1
  local f = 4.0 * E_STAR * a ^ 3 / (3.0 * R)  -- force on the whole sphere giving the contact radius a
  return { modelisation = '3D', q = f / (math.pi * R ^ 2), p0 = 3.0 * f / (2.0 * math.pi * a ^ 2),
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

local function run(family, k, m)
  local sc = scene(family)
  local mesh_file = 'meshes/hertz_' .. family:lower():gsub('[^%w]', '') .. '_k' .. k .. '.med'
  local para, vale = { 'family', 'method', 'k', 'status' }, { family, m.name, tostring(k) }
  local cham, cmp = 'DEPL', 'LAGS_C'
  if m.kind ~= 'MORTAR' and m.kind ~= 'CONTINUE' then cham, cmp = 'CONT_NOEU', 'PRES' end
  local err = _F{ NOM = 'err_p0', NOM_CHAM = cham, NOM_CMP = cmp, GROUP_NO = 'O_BLOCK', VALE_REFE = -sc.p0 }
  local ok, r = pcall(solve, mesh_file, m, sc)
  if ok then
    vale[#vale + 1] = 'ok'
    IMPR_MESURE{ FICHIER = 'chart_hertz.csv', RESULTAT = r, PARA = para, VALE_K = vale, ERREUR = err }
  else
    local message = tostring(r):gsub('\n.*', '')
    print('study: ' .. mesh_file .. ' ' .. m.name .. ' failed: ' .. message)
    vale[#vale + 1] = 'failed: ' .. message
    IMPR_MESURE{ FICHIER = 'chart_hertz.csv', PARA = para, VALE_K = vale, ERREUR = err }
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
