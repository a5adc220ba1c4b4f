-- FORCE_INTERNE, a force per unit volume on the model's cells: the unit square / cube (distorted
-- patch meshes) and an AXIS section [1,2]x[0,1] (distorted, axis_patch_*.med), held on BOTTOM in
-- the direction of the load (DY, or DZ in 3D) and by symmetry on LEFT (DX; 3D also DY on FRONT),
-- loaded by f = -F along that direction, on TOUT or on GROUP_MA BLOCK. Equilibrium: the base
-- reaction (REAC_NODA) sums to +F V, V = 1 (per unit thickness, m3) and, in AXIS, the volume per
-- radian integral of r dA = (2^2 - 1^2) / 2 = 1.5. The consistent forces integrate N_a |J| (times
-- r) exactly with the cells' full rule on these straight-sided cells, and the sum of the nodal
-- reactions holds to the solver's round-off: tolerance 1e-10.
-- No VALE_CALC: every check is analytical at the tolerance an exact method allows.
-- Reference: analytical (equilibrium). Units SI. Runtime label: fast.
DEBUT()
local F = 2.5e4
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
local cases = {
  { file = 'patch_quad4', model = 'D_PLAN', vol = 1.0 }, { file = 'patch_tria6', model = 'C_PLAN', vol = 1.0 },
  { file = 'axis_patch_quad4', model = 'AXIS', vol = 1.5 }, { file = 'axis_patch_quad8', model = 'AXIS', vol = 1.5 },
  { file = 'patch_hexa20', model = '3D', vol = 1.0 }, { file = 'patch_tetra4', model = '3D', vol = 1.0 },
}
for i, c in ipairs(cases) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/' .. c.file .. '.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = c.model } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  local up = c.model == '3D' and 'DZ' or 'DY'
  local ddl = { _F{ GROUP_MA = 'BOTTOM', [up] = 0.0 } }
  if c.model ~= 'AXIS' then ddl[#ddl + 1] = _F{ GROUP_MA = 'LEFT', DX = 0.0 } end  -- AXIS: the hoop holds r
  if c.model == '3D' then ddl[#ddl + 1] = _F{ GROUP_MA = 'FRONT', DY = 0.0 } end
  local where = i % 2 == 1 and { TOUT = 'OUI' } or { GROUP_MA = 'BLOCK' }
  local force = _F(where)
  force['F' .. up:sub(2)] = -F
  local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = ddl, FORCE_INTERNE = force }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, FORCE = 'REAC_NODA' }
  local T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'BASE', RESULTAT = R,
                                        NOM_CHAM = 'REAC_NODA', GROUP_NO = 'BOTTOM', RESULTANTE = up,
                                        NUME_ORDRE = 1 } }
  TEST_TABLE{ TABLE = T, NOM_PARA = up, LEGENDE = c.file .. ' ' .. c.model, REFERENCE = 'ANALYTIQUE',
              VALE_REFE = F * c.vol, PRECISION = 1.0e-10 }
end
FIN()
