-- Probe (not a verification deck): the discrete contact pressure node by node near the axis of
-- the study's axisymmetric Hertz scene (tests/bench/study/chart_hertz.lua, family AXIS-G k = 8),
-- against Hertz. It shows why the study's CONTRAINTE and PENALISATION rows of the AXIS families
-- stay about 50 % off at r = 0 whatever the mesh, while the nodes next to the axis are within a
-- few per cent (tests/bench/README.md, "Hertz rows that measure no convergence").
-- Mesh, next to this deck:
--   build/lunaster-meshgen --hertz quad8:20 --grading 1.5 --refine 8 -o tests/bench/hertz_axis_nodes.med
-- then: build/lunaster run tests/bench/hertz_axis_nodes.lua -q (a probe: it checks nothing and says NO_CHECK)
local R, E, NU, a = 1.0, 1.0e9, 0.3, 0.1
local E_STAR = 1.0 / (2.0 * (1.0 - NU ^ 2) / E)
local f = 4.0 * E_STAR * a ^ 3 / (3.0 * R)  -- the load that gives the contact radius a
local p0 = 3.0 * f / (2.0 * math.pi * a ^ 2)
DEBUT()
local ma = LIRE_MAILLAGE{ FORMAT = 'MED' }
local mo = AFFE_MODELE{ MAILLAGE = ma, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
local cm = AFFE_MATERIAU{ MAILLAGE = ma, AFFE = _F{ TOUT = 'OUI', MATER = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } } } }
local cha = AFFE_CHAR_MECA{ MODELE = mo,
                            DDL_IMPO = { _F{ GROUP_MA = { 'AXIS_BALL', 'AXIS_BLOCK' }, DX = 0.0 },
                                         _F{ GROUP_MA = 'BLOCK_BOTTOM', DX = 0.0, DY = 0.0 } },
                            PRES_REP = _F{ GROUP_MA = 'BALL_TOP', PRES = f / (math.pi * R ^ 2) } }
local contact = AFFE_CHAR_MECA{ MODELE = mo, CONTACT = _F{ METHODE = 'CONTRAINTE', GROUP_MA_ESCL = 'BLOCK_TOP',
                                                           GROUP_MA_MAIT = 'BALL_SURF', CONTACT_INIT = 'OUI',
                                                           REAC_GEOM = 'SANS' } }
local r = STAT_NON_LINE{ MODELE = mo, CHAM_MATER = cm, EXCIT = { _F{ CHARGE = cha }, _F{ CHARGE = contact } },
                         COMPORTEMENT = _F{ RELATION = 'ELAS' }, CONVERGENCE = _F{ ITER_GLOB_MAXI = 40 },
                         INCREMENT = _F{ LIST_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } } } }
local t = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'P', RESULTAT = r, NOM_CHAM = 'CONT_NOEU',
                                      GROUP_NO = 'BLOCK_TOP', NOM_CMP = 'PRES', NUME_ORDRE = 1 } }
local rows = {}
for i = 1, #t.PRES do
  local ok, p = pcall(function() return t.PRES[i] end)  -- only the slave vertices carry PRES
  if ok and p ~= nil and t.COOR_X[i] <= a then rows[#rows + 1] = { t.COOR_X[i], -p } end
end
table.sort(rows, function(u, v) return u[1] < v[1] end)
print(string.format('%10s %14s %14s %8s', 'r (m)', 'p (Pa)', 'Hertz p(r)', 'p/p(r)'))
for _, q in ipairs(rows) do
  local exact = p0 * math.sqrt(math.max(1.0 - (q[1] / a) ^ 2, 0.0))
  print(string.format('%10.5f %14.6e %14.6e %8.4f', q[1], q[2], exact, q[2] / exact))
end
FIN()
