-- study.lua: one SSNP121 run as a function, for the speed/accuracy study decks.
-- A run reads its mesh, builds the model, solves with one contact method, computes
-- SIGM_NOEU and appends one row (cost + errors against the exact solution) to a
-- CSV file with IMPR_MESURE. Failures are caught (pcall) and recorded as rows too.
--
-- Exact solution (both dimensions): uniform strain -0.05, contact pressure -1e5 Pa,
-- interface displacement -0.05 m. Error columns (relative, max over the nodes):
--   err_p      the method's contact pressure over the slave surface
--              (CONTINUE and MORTAR: LAGS_C; discrete: CONT_NOEU PRES)
--   err_sig    the normal stress SIGM_NOEU (SIYY 2D, SIZZ 3D) over both interface sides
--   err_A/O/B  contact pressure at the points A, O, B of AB (CONTINUE: LAGS_C,
--              discrete: SIGM_NOEU SIYY as in code_aster's SSNP121 B/C); 3D: A21/A22/A23
--   err_u      normal displacement over both interface sides
local M = {}

M.E, M.NU, M.U0, M.P = 2.0e6, 0.0, -0.1, -1.0e5

--- The contact methods of the chart: name, kind and settings.
function M.methods()
  return {
    { name = 'CONTINUE-GAUSS', kind = 'CONTINUE', integration = 'GAUSS', ordre = 3, coef = 1000.0 },
    { name = 'CONTINUE-SIMPSON', kind = 'CONTINUE', integration = 'SIMPSON', ordre = 4, coef = 1000.0 },
    { name = 'CONTINUE-NCOTES', kind = 'CONTINUE', integration = 'NCOTES', ordre = 8, coef = 1000.0 },
    { name = 'CONTRAINTE', kind = 'CONTRAINTE' },
    { name = 'PENALISATION-1e7', kind = 'PENALISATION', e_n = 1.0e7 },
    { name = 'PENALISATION-1e9', kind = 'PENALISATION', e_n = 1.0e9 },
    { name = 'PENALISATION-1e11', kind = 'PENALISATION', e_n = 1.0e11 },
    { name = 'MORTAR', kind = 'MORTAR', algo = 'LAGRANGIEN', init = 'INTERPENETRE' },
    { name = 'MORTAR-PEN-1e11', kind = 'MORTAR', algo = 'PENALISATION', coef = 1.0e11, init = 'INTERPENETRE' },
  }
end

local function fmt(v)
  if type(v) == 'number' then return string.format('%.6g', v) end
  return tostring(v)
end

--- Geometry names of a dimension: groups, loaded faces, normal component.
local function scene(dim)
  if dim == 2 then
    return { modelisation = 'D_PLAN', bodies = { 'PLAQUE1', 'PLAQUE2' }, top = 'CD', bottom = 'GH',
             upper_face = 'AB', lower_face = 'EF', normal = 'DY', sig = 'SIYY', points = { 'A', 'O', 'B' },
             fixed = function(v) return { DX = 0.0, DY = v } end }
  end
  return { modelisation = '3D', bodies = { 'V1', 'V2' }, top = 'SURCHA', bottom = 'ENCAST',
           upper_face = 'SURESC', lower_face = 'SURMAI', normal = 'DZ', sig = 'SIZZ', points = { 'A21', 'A22', 'A23' },
           fixed = function(v) return { DX = 0.0, DY = 0.0, DZ = v } end }
end

--- Contact definition of a method; returns (DEFI_CONTACT concept or nil, contact load or nil, slave group).
local function contact_of(mo, m, sc)
  -- CONTINUE takes the seed's model A roles (slave AB, or SURESC in 3D); discrete
  -- methods take models B/C roles (slave EF, or SURMAI in 3D).
  if m.kind == 'CONTINUE' and m.integration == 'NOEUD' then
    -- NOEUD exists only in the seed's syntax: the same zone as a contact load.
    local slave, master = m.slave or sc.upper_face, m.master or sc.lower_face
    return nil, AFFE_CHAR_MECA{ MODELE = mo, CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = slave, GROUP_MA_MAIT = master,
                                INTEGRATION = 'NOEUD', COEF_CONT = m.coef, CONTACT_INIT = m.init or 'NON',
                                ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE', REAC_GEOM = 'CONTROLE',
                                NB_ITER_GEOM = 2 } }, slave
  end
  if m.kind == 'MORTAR' then
    local slave, master = m.slave or sc.upper_face, m.master or sc.lower_face
    local zone = { APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = slave, GROUP_MA_MAIT = master, ALGO_CONT = m.algo,
                   CONTACT_INIT = m.init or 'INTERPENETRE' }
    if m.coef then zone.COEF_CONT = m.coef end
    return DEFI_CONT{ MODELE = mo, ZONE = _F(zone) }, nil, slave
  end
  if m.kind == 'CONTINUE' then
    local slave, master = m.slave or sc.upper_face, m.master or sc.lower_face
    local zone = { GROUP_MA_ESCL = slave, GROUP_MA_MAIT = master, INTEGRATION = m.integration,
                   COEF_CONT = m.coef, CONTACT_INIT = m.init or 'NON' }
    if m.ordre then zone.ORDRE_INT = m.ordre end
    return DEFI_CONTACT{ MODELE = mo, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE',
                         ALGO_RESO_GEOM = 'POINT_FIXE', REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
                         ZONE = _F(zone) }, nil, slave
  end
  local slave, master = m.slave or sc.lower_face, m.master or sc.upper_face
  local c = { METHODE = m.kind, GROUP_MA_ESCL = slave, GROUP_MA_MAIT = master, REAC_GEOM = 'AUTOMATIQUE' }
  if m.kind == 'PENALISATION' then c.E_N = m.e_n end
  return nil, AFFE_CHAR_MECA{ MODELE = mo, CONTACT = _F(c) }, slave
end

--- Builds and solves one case; returns the result (error raised on failure).
local function solve(mesh_file, m, dim, opts)
  local sc = scene(dim)
  local ma = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = mesh_file }
  local mo = AFFE_MODELE{ MAILLAGE = ma, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = sc.modelisation } }
  local mat = DEFI_MATERIAU{ ELAS = _F{ E = M.E, NU = M.NU } }
  local cm = AFFE_MATERIAU{ MAILLAGE = ma, AFFE = _F{ GROUP_MA = sc.bodies, MATER = mat } }
  local top = sc.fixed(M.U0)
  top.GROUP_NO = sc.top
  local bottom = sc.fixed(0.0)
  bottom.GROUP_NO = sc.bottom
  local bc = AFFE_CHAR_MECA{ MODELE = mo, DDL_IMPO = { _F(top), _F(bottom) } }
  local cont, cont_load, slave = contact_of(mo, m, sc)
  local excit = { _F{ CHARGE = bc, FONC_MULT = M.ramp() } }
  if cont_load then excit[#excit + 1] = _F{ CHARGE = cont_load } end
  local snl = { MODELE = mo, CHAM_MATER = cm, EXCIT = excit, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                INCREMENT = _F{ LIST_INST = M.times() },
                CONVERGENCE = _F{ RESI_GLOB_RELA = opts.resi or 1e-6, ITER_GLOB_MAXI = opts.iter or 30 } }
  if cont then snl.CONTACT = cont end
  if opts.solver then snl.SOLVEUR = _F{ METHODE = opts.solver } end
  local r = STAT_NON_LINE(snl)
  r = CALC_CHAMP{ reuse = r, RESULTAT = r, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
  return r, sc, slave
end

local times_, ramp_
function M.times()
  times_ = times_ or DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
  return times_
end
function M.ramp()
  ramp_ = ramp_ or DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
  return ramp_
end

--- The error columns of a result.
local function errors(sc, m, slave, with_points)
  local p_cham, p_cmp = 'CONT_NOEU', 'PRES'
  if m.kind == 'CONTINUE' or m.kind == 'MORTAR' then p_cham, p_cmp = 'DEPL', 'LAGS_C' end
  local faces = { sc.upper_face, sc.lower_face }
  local e = {
    _F{ NOM = 'err_p', NOM_CHAM = p_cham, NOM_CMP = p_cmp, GROUP_MA = slave, VALE_REFE = M.P },
    _F{ NOM = 'err_sig', NOM_CHAM = 'SIGM_NOEU', NOM_CMP = sc.sig, GROUP_MA = faces, VALE_REFE = M.P },
  }
  local point_cham, point_cmp = 'SIGM_NOEU', sc.sig
  if (m.kind == 'CONTINUE' or m.kind == 'MORTAR') and (m.slave == nil or m.slave == sc.upper_face) then
    point_cham, point_cmp = 'DEPL', 'LAGS_C'
  end
  for i, name in ipairs(with_points and { 'err_A', 'err_O', 'err_B' } or {}) do
    e[#e + 1] = _F{ NOM = name, NOM_CHAM = point_cham, NOM_CMP = point_cmp, GROUP_NO = sc.points[i], VALE_REFE = M.P }
  end
  e[#e + 1] = _F{ NOM = 'err_u', NOM_CHAM = 'DEPL', NOM_CMP = sc.normal, GROUP_MA = faces, VALE_REFE = M.U0 / 2 }
  return e
end

--- Runs one case and appends its row to `csv`. `labels` is an ordered list of
--- {name, value} pairs written first; a failure is recorded in the column
--- `status` with the first line of its message. opts: solver, resi, iter, and
--- points = false to leave out err_A/O/B (meshes without a node at O). Returns the result or nil.
function M.run(csv, labels, mesh_file, m, dim, opts)
  opts = opts or {}
  local para, vale = {}, {}
  for _, kv in ipairs(labels) do para[#para + 1] = kv[1]; vale[#vale + 1] = fmt(kv[2]) end
  local ok, r, sc, slave = pcall(solve, mesh_file, m, dim, opts)
  para[#para + 1] = 'status'
  if ok then
    vale[#vale + 1] = 'ok'
    IMPR_MESURE{ FICHIER = csv, RESULTAT = r, PARA = para, VALE_K = vale, ERREUR = errors(sc, m, slave, opts.points ~= false) }
    return r
  end
  local message = tostring(r):gsub('\n.*', '')
  print('study: ' .. mesh_file .. ' ' .. m.name .. ' failed: ' .. message)
  vale[#vale + 1] = 'failed: ' .. message
  IMPR_MESURE{ FICHIER = csv, PARA = para, VALE_K = vale, ERREUR = errors(scene(dim), m, m.slave or scene(dim).upper_face, opts.points ~= false) }
  return nil
end

return M
