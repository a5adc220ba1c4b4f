-- Nodal forces, groups made by DEFI_GROUP, a model and materials on a cell group, a time list
-- cut by PAS, and the output commands (IMPR_RESU of a mesh, IMPR_MESURE), on one-cell unit blocks.
-- Purpose: a uniform traction q on the top face, given as its consistent nodal forces
--          (FORCE_NODALE: q/2 on each top node of a QUAD4 edge, q/4 on each top node of a HEXA8
--          face), with symmetry conditions leaving a uniform exact field that one bilinear /
--          trilinear cell reproduces to round-off. The nodes are named by lunaster-meshgen
--          (unit_quad4.med: N1..N4 = C00 C10 C11 C01, cell M5 = the QUAD4, after the four SEG2): the forces use NOEUD
--          'N3' and a node group made by DEFI_GROUP from NOEUD 'N4'; the model and materials use
--          a cell group made from MAILLE 'M5'. Loads ramp linearly in time (PAS = 0.5).
-- Reference: analytical (Hooke's law). 2D plane strain: SIYY = -q, DY(top) = -q (1 - NU^2) / E,
--            DX(right) = q NU (1 + NU) / E. 3D: SIZZ = -q, DZ(top) = -q / E, DX(right) =
--            DY(back) = q NU / E. Values at INST t are t times these. Units SI. Runtime label: fast.
DEBUT()
local E, NU, Q = 2.0e6, 0.3, 1.0e4
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, PAS = 0.5 } }

-- 2D, plane strain
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/unit_quad4.med' }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA,
                 CREA_GROUP_MA = { _F{ NOM = 'SOLID', MAILLE = 'M5' }, _F{ NOM = 'SIDES', GROUP_MA = { 'LEFT', 'RIGHT' } } },
                 CREA_GROUP_NO = { _F{ GROUP_MA = 'TOP', NOM = 'TOP_NODES' }, _F{ NOEUD = 'N4', NOM = 'CORNER_01' },
                                   _F{ TOUT_GROUP_MA = 'OUI' } } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = 'SOLID', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, MODELE = MO, AFFE = _F{ GROUP_MA = 'SOLID', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 } },
                     FORCE_NODALE = { _F{ NOEUD = 'N3', FY = -Q / 2 }, _F{ GROUP_NO = 'CORNER_01', FX = 0.0, FY = -Q / 2 } } }
R2 = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                    COMPORTEMENT = _F{ RELATION = 'ELAS', GROUP_MA = 'SOLID' }, INCREMENT = _F{ LIST_INST = L } }
R2 = CALC_CHAMP{ reuse = R2, RESULTAT = R2, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
local checks = {}
local function check(r, inst, cham, cmp, kind, group, refe)
  checks[#checks + 1] = _F{ RESULTAT = r, INST = inst, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind,
                            GROUP_NO = group, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10 }
end
for _, t in ipairs({ 0.5, 1.0 }) do
  local dy = -Q * (1 - NU * NU) / E * t
  check(R2, t, 'DEPL', 'DY', 'MIN', 'TOP_NODES', dy)
  check(R2, t, 'DEPL', 'DY', 'MAX', 'TOP_NODES', dy)
  check(R2, t, 'DEPL', 'DX', 'MAX', 'SIDES', Q * NU * (1 + NU) / E * t)  -- the right side; the left is fixed
  check(R2, t, 'SIGM_NOEU', 'SIYY', 'MIN', nil, -Q * t)
  check(R2, t, 'SIGM_NOEU', 'SIYY', 'MAX', nil, -Q * t)
end

-- 3D
M3 = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/unit_hexa8.med' }
M3 = DEFI_GROUP{ reuse = M3, MAILLAGE = M3, CREA_GROUP_NO = _F{ GROUP_MA = 'TOP' } }
MO3 = AFFE_MODELE{ MAILLAGE = M3, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CM3 = AFFE_MATERIAU{ MAILLAGE = M3, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH3 = AFFE_CHAR_MECA{ MODELE = MO3,
                      DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'FRONT', DY = 0.0 },
                                   _F{ GROUP_NO = 'BOTTOM', DZ = 0.0 } },
                      FORCE_NODALE = _F{ GROUP_NO = 'TOP', FZ = -Q / 4 } }
R3 = STAT_NON_LINE{ MODELE = MO3, CHAM_MATER = CM3, EXCIT = _F{ CHARGE = CH3, FONC_MULT = RAMPE },
                    COMPORTEMENT = _F{ RELATION = 'ELAS', TOUT = 'OUI' }, INCREMENT = _F{ LIST_INST = L } }
R3 = CALC_CHAMP{ reuse = R3, RESULTAT = R3, CONTRAINTE = 'SIGM_NOEU' }
check(R3, 1.0, 'DEPL', 'DZ', 'MIN', 'TOP', -Q / E)
check(R3, 1.0, 'DEPL', 'DZ', 'MAX', 'TOP', -Q / E)
check(R3, 1.0, 'DEPL', 'DX', 'MAX', 'RIGHT', Q * NU / E)
check(R3, 1.0, 'DEPL', 'DX', 'MIN', 'RIGHT', Q * NU / E)
check(R3, 1.0, 'DEPL', 'DY', 'MAX', 'BACK', Q * NU / E)
check(R3, 0.5, 'SIGM_NOEU', 'SIZZ', 'MIN', nil, -Q / 2)
check(R3, 0.5, 'SIGM_NOEU', 'SIZZ', 'MAX', nil, -Q / 2)
TEST_RESU{ RESU = checks }

-- Output: the mesh alone in MED, the last step's DEPL and SIGM_NOEU, and one measurement row
-- (errors against the exact solution).
IMPR_RESU{ FORMAT = 'MED', FICHIER = 'unit_quad4_groups.rmed', RESU = _F{ MAILLAGE = MA } }
IMPR_RESU{ FORMAT = 'MED', FICHIER = 'unit_quad4_last.rmed',
           RESU = _F{ RESULTAT = R2, MAILLAGE = MA, NOM_CHAM = { 'DEPL', 'SIGM_NOEU' }, NUME_ORDRE = 2 } }
IMPR_MESURE{ FICHIER = 'loads_and_groups.csv', RESULTAT = R2, PARA = { 'case' }, VALE_K = { 'quad4' },
             ERREUR = { _F{ NOM = 'err_dy', NOM_CHAM = 'DEPL', NOM_CMP = 'DY', GROUP_NO = 'TOP_NODES', NUME_ORDRE = 2,
                            VALE_REFE = -Q * (1 - NU * NU) / E },
                        _F{ NOM = 'err_siyy', NOM_CHAM = 'SIGM_NOEU', NOM_CMP = 'SIYY', GROUP_MA = 'SOLID', VALE_REFE = -Q } } }
FIN()
