-- Benchmark (not a verification deck): the glued elastic solve of ssnp121i_refined_mortar.lua's mesh
-- (V1 50x50x10 HEXA8 under V2 40x40x10 HEXA20, about 3.2e5 unknowns): LIAISON_MAIL ties each node of
-- the QUAD4 face SURESC to the HEXA20 cells of V2 it lies in (non-matching), each relation solved for
-- its slave unknown (SOLVEUR ELIM_LAGR = 'OUI': an SPD system, no multipliers), so it is the mortar
-- case's elastic reference on the same mesh: the same loads, the same analytical field.
-- Generate the mesh next to this deck first:
--   build/lunaster-meshgen --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine 10 -o tests/bench/ssnp121i_refined.med
-- then: /usr/bin/time -v build/lunaster run tests/bench/ssnp121i_refined_glued.lua -q
-- (tests/bench/contact_parts.sh runs it on a mesh in parts beside the mortar deck).
-- Checks: the analytical values at 5e-3. LIAISON_MAIL, a node-to-cell tie, misses the patch test on a
-- non-matching interface: each slave node's force reaches the HEXA20 master nodes through the master
-- cell's shape functions, not as a uniform traction's consistent loads. Measured (serially and in
-- parts alike): DZ -4.984305837e-02 at the corners A21..A24 (3.1e-3), -5.003664799e-02 at the
-- lowest node of SURESC (7.3e-4); the mortar deck on this mesh is exact to 1e-12.
-- Runtime label: slow, benchmark.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121i_refined.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } },
                       LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURESC' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST },
                      SOLVEUR = _F{ ELIM_LAGR = 'OUI' } }

local checks = {}
local function check(cmp, refe, group, kind)
  checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = cmp, GROUP_NO = group,
                            TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 5.0e-3 }
end
for _, point in ipairs({ 'A21', 'A22', 'A23', 'A24' }) do check('DZ', -0.05, point) end
check('DZ', -0.05, 'SURESC', 'MIN')
check('DZ', -0.05, 'SURESC', 'MAX')
TEST_RESU{ RESU = checks }
FIN()
