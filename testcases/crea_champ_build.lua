-- CREA_CHAMP's fields built at nodes, as code_aster's contact decks build an analytical solution
-- and its difference with the computed one: EXTR of a mesh's GEOMETRIE, AFFE (constants on
-- groups, or functions, NOEU_NEUT_F), EVAL (the functions at each node, X and Y from the
-- geometry), ASSE (components renamed, scaled and added, CUMUL) and COMB (a linear combination).
-- Scene: the distorted unit square of QUAD8 (patch_quad8.med, 40 nodes, 7 on TOP), D_PLAN,
-- E = 2e6, NU = 0.3, LEFT DX = 0, BOTTOM DY = 0, TOP DY = -0.01: a uniform strain.
-- Reference: analytical. The exact displacement is DX = NU/(1-NU) 0.01 X, DY = -0.01 Y at every
-- node (linear, reproduced by QUAD8 to round-off); the analytical field built from it by AFFE,
-- EVAL and ASSE equals the computed one, and their difference (COMB, or ASSE with CUMUL) is zero
-- on the scale 1e-2. Constants: DX = 1 everywhere but 5 on TOP sums to 33 + 7 x 5 = 68. Units SI.
-- Runtime label: fast.
DEBUT()
local NU, U0 = 0.3, -0.01
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_quad8.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = NU } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = U0 } } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L } }
U = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_DEPL_R', NOM_CHAM = 'DEPL', RESULTAT = R, NUME_ORDRE = 1 }

-- The analytical solution as functions of the geometry.
F_DX = FORMULE{ VALE = 'NU / (1 - NU) * 0.01 * X', NOM_PARA = 'X', NU = NU }
F_DY = FORMULE{ VALE = 'U0 * Y', NOM_PARA = 'Y', U0 = U0 }
CHXN = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_GEOM_R', NOM_CHAM = 'GEOMETRIE', MAILLAGE = MA }
FANA = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_NEUT_F', MAILLAGE = MA,
                   AFFE = _F{ TOUT = 'OUI', NOM_CMP = { 'X1', 'X2' }, VALE_F = { F_DX, F_DY } } }
NANA = CREA_CHAMP{ OPERATION = 'EVAL', TYPE_CHAM = 'NOEU_NEUT_R', CHAM_F = FANA, CHAM_PARA = CHXN }
UANA = CREA_CHAMP{ OPERATION = 'ASSE', TYPE_CHAM = 'NOEU_DEPL_R', MAILLAGE = MA,
                   ASSE = _F{ TOUT = 'OUI', CHAM_GD = NANA, NOM_CMP = { 'X1', 'X2' }, NOM_CMP_RESU = { 'DX', 'DY' } } }
-- The difference, twice: a linear combination, and an assembly adding to what is there.
DIFF = CREA_CHAMP{ OPERATION = 'COMB', TYPE_CHAM = 'NOEU_DEPL_R',
                   COMB = { _F{ CHAM_GD = U, COEF_R = 1.0 }, _F{ CHAM_GD = UANA, COEF_R = -1.0 } } }
DIFF2 = CREA_CHAMP{ OPERATION = 'ASSE', TYPE_CHAM = 'NOEU_DEPL_R', MODELE = MO,
                    ASSE = { _F{ TOUT = 'OUI', CHAM_GD = U, CUMUL = 'OUI', COEF_R = 1.0 },
                             _F{ TOUT = 'OUI', CHAM_GD = UANA, CUMUL = 'OUI', COEF_R = -1.0 } } }
-- Constants on groups: a later occurrence overrides an earlier one.
CST = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_DEPL_R', MODELE = MO,
                  AFFE = { _F{ TOUT = 'OUI', NOM_CMP = { 'DX', 'DY' }, VALE = { 1.0, 2.0 } },
                           _F{ GROUP_NO = 'TOP', NOM_CMP = 'DX', VALE = 5.0 } } }
-- CUMUL = 'NON' replaces: on TOP, DY gets CST's DX (5), then 3 x CST's DY (6) in its place; off TOP, no DY.
TOP3 = CREA_CHAMP{ OPERATION = 'ASSE', TYPE_CHAM = 'NOEU_DEPL_R', MAILLAGE = MA,
                   ASSE = { _F{ GROUP_NO = 'TOP', CHAM_GD = CST, NOM_CMP = 'DX', NOM_CMP_RESU = 'DY' },
                            _F{ GROUP_NO = 'TOP', CHAM_GD = CST, NOM_CMP = 'DY', COEF_R = 3.0 } } }
T20 = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_TEMP_R', MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', NOM_CMP = 'TEMP', VALE = 20.0 } }

local DXMAX = NU / (1 - NU) * 0.01
local function check(field, cmp, test, refe, calc, group, extra)
  local occ = { CHAM_GD = field, NOM_CMP = cmp, TYPE_TEST = test, GROUP_NO = group, REFERENCE = 'ANALYTIQUE',
                VALE_REFE = refe, PRECISION = 1.0e-10, VALE_CALC = calc }
  for k, v in pairs(extra or {}) do occ[k] = v end
  return _F(occ)
end
local zero = { CRITERE = 'ABSOLU', ORDRE_GRANDEUR = 1.0e-2, PRECISION = 1.0e-12, TOLE_MACHINE = 1.0e-12 }
TEST_RESU{ CHAM_NO = {
  check(CHXN, 'X', 'MAX', 1.0, 1.0),
  check(CHXN, 'Y', 'MIN', 0.0, 0.0, nil, { CRITERE = 'ABSOLU' }),
  check(NANA, 'X1', 'MAX', DXMAX, DXMAX),
  check(UANA, 'DY', 'MIN', U0, U0, 'TOP'),
  check(U, 'DX', 'MAX', DXMAX, DXMAX, 'RIGHT'),
  check(DIFF, 'DX', 'SOMM_ABS', 0.0, 0.0, nil, zero),
  check(DIFF, 'DY', 'SOMM_ABS', 0.0, 0.0, nil, zero),
  check(DIFF2, 'DX', 'SOMM_ABS', 0.0, 0.0, nil, zero),
  check(DIFF2, 'DY', 'SOMM_ABS', 0.0, 0.0, nil, zero),
  check(CST, 'DX', 'SOMM', 33 * 1.0 + 7 * 5.0, 68.0),
  check(CST, 'DY', 'SOMM', 40 * 2.0, 80.0),
  check(TOP3, 'DY', 'SOMM', 7 * 3 * 2.0, 42.0),
  check(T20, 'TEMP', 'SOMM', 40 * 20.0, 800.0),
} }
FIN()
