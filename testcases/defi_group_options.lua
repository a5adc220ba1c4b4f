-- DEFI_GROUP's options as code_aster's contact decks use them: node groups by geometry (OPTION =
-- 'PLAN', 'ENV_SPHERE', 'ENV_CYLINDRE'), along a segment or a line of cells ('SEGM_DROI_ORDO',
-- 'NOEUD_ORDO' with GROUP_NO_ORIG / GROUP_NO_EXTR), CRIT_NOEUD, and node and cell groups made
-- by INTERSEC, UNION and DIFFE.
-- Scene: the distorted unit square of QUAD8 (patch_quad8.med: 40 nodes, its sides straight, 3
-- SEG3 cells each, groups TOP, BOTTOM, LEFT, RIGHT) and the unit cube of one HEXA8.
-- Reference: analytical, by counting. A group's node count is the sum over it of a field of ones
-- (CREA_CHAMP AFFE), its coordinates' sums those of the geometry (EXTR GEOMETRIE). A side holds
-- 7 nodes (4 corners of its cells, 3 mid-side), at abscissae k/6: their X on TOP add up to 3.5.
-- The unit circle about (0, 0) passes through 2 nodes, (1, 0) and (0, 1); the cylinder of radius
-- 1 about the cube's edge along Z through 4 of its 8 nodes, Z adding up to 2. Units SI.
-- Runtime label: fast.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_quad8.med' }
local function corner(name, x, y)  -- a one-node group, as code_aster's decks make them
  return _F{ NOM = name, OPTION = 'ENV_SPHERE', POINT = { x, y }, RAYON = 1.0e-3, PRECISION = 1.0e-3 }
end
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA,
  CREA_GROUP_MA = { _F{ NOM = 'TOP_LEFT', UNION = { 'TOP', 'LEFT' } },
                    _F{ NOM = 'TOP_AGAIN', DIFFE = { 'TOP_LEFT', 'LEFT' } },
                    _F{ NOM = 'LEFT_AGAIN', INTERSEC = { 'TOP_LEFT', 'LEFT' } } },
  CREA_GROUP_NO = {
    _F{ NOM = 'Y1', OPTION = 'PLAN', POINT = { 0.0, 1.0 }, VECT_NORMALE = { 0.0, 2.0 }, PRECISION = 1.0e-9 },
    _F{ NOM = 'DIAG', OPTION = 'PLAN', POINT = { 0.0, 0.0 }, VECT_NORMALE = { 1.0, -1.0 }, PRECISION = 1.0e-9 },
    _F{ NOM = 'CIRCLE', OPTION = 'ENV_SPHERE', POINT = { 0.0, 0.0 }, RAYON = 1.0, PRECISION = 1.0e-9 },
    corner('A', 0.0, 1.0), corner('B', 1.0, 1.0), corner('O', 0.0, 0.0),
    _F{ NOM = 'TOP_SEGM', OPTION = 'SEGM_DROI_ORDO', GROUP_NO = 'TOP', GROUP_NO_ORIG = 'B', GROUP_NO_EXTR = 'A',
        PRECISION = 1.0e-6, CRITERE = 'RELATIF' },
    -- the line TOP then LEFT, from B: stopped at A it is TOP, gone to its end it holds LEFT too
    _F{ NOM = 'B_TO_A', OPTION = 'NOEUD_ORDO', GROUP_MA = 'TOP_LEFT', GROUP_NO_ORIG = 'B', GROUP_NO_EXTR = 'A' },
    _F{ NOM = 'B_TO_O', OPTION = 'NOEUD_ORDO', GROUP_MA = 'TOP_LEFT', GROUP_NO_ORIG = 'B' },
    _F{ NOM = 'TOP_CORNERS', GROUP_MA = 'TOP', CRIT_NOEUD = 'SOMMET' },
    _F{ NOM = 'TOP_MIDDLES', GROUP_MA = 'TOP', CRIT_NOEUD = 'MILIEU' },
    _F{ NOM = 'TOP_AND_Y1', INTERSEC = { 'TOP', 'Y1' } },
    _F{ NOM = 'TOP_OR_BOTTOM', UNION = { 'TOP', 'BOTTOM' } },
    _F{ NOM = 'TOP_INNER', DIFFE = { 'TOP', 'A', 'B' } },
  } }
ONES = CREA_CHAMP{ OPERATION = 'AFFE', TYPE_CHAM = 'NOEU_NEUT_R', MAILLAGE = MA,
                   AFFE = _F{ TOUT = 'OUI', NOM_CMP = 'X1', VALE = 1.0 } }
XYZ = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_GEOM_R', NOM_CHAM = 'GEOMETRIE', MAILLAGE = MA }

local function count(group, n)
  return _F{ CHAM_GD = ONES, NOM_CMP = 'X1', GROUP_NO = group, TYPE_TEST = 'SOMM', LEGENDE = group .. ' nodes',
             REFERENCE = 'ANALYTIQUE', VALE_REFE = n, PRECISION = 0.0, CRITERE = 'ABSOLU', VALE_CALC = n }
end
local function sum(field, cmp, group, value, test)
  return _F{ CHAM_GD = field, NOM_CMP = cmp, GROUP_NO = group, TYPE_TEST = test or 'SOMM', LEGENDE = group,
             REFERENCE = 'ANALYTIQUE', VALE_REFE = value, PRECISION = 1.0e-12, CRITERE = 'ABSOLU', VALE_CALC = value }
end
TEST_RESU{ CHAM_NO = {
  count('Y1', 7), sum(XYZ, 'X', 'Y1', 3.5), sum(XYZ, 'Y', 'Y1', 1.0, 'MIN'),
  count('DIAG', 2), sum(XYZ, 'X', 'DIAG', 1.0),  -- (0, 0) and (1, 1): the diagonal's other nodes are distorted
  count('CIRCLE', 2), sum(XYZ, 'X', 'CIRCLE', 1.0),
  count('A', 1), sum(XYZ, 'X', 'A', 0.0), sum(XYZ, 'Y', 'A', 1.0),
  count('TOP_SEGM', 7), sum(XYZ, 'X', 'TOP_SEGM', 3.5),
  count('B_TO_A', 7), sum(XYZ, 'Y', 'B_TO_A', 7.0),
  count('B_TO_O', 13), sum(XYZ, 'X', 'B_TO_O', 3.5), sum(XYZ, 'Y', 'B_TO_O', 7.0 + 3.5 - 1.0),
  count('TOP_CORNERS', 4), sum(XYZ, 'X', 'TOP_CORNERS', 0.0 + 1 / 3 + 2 / 3 + 1.0),
  count('TOP_MIDDLES', 3), sum(XYZ, 'X', 'TOP_MIDDLES', 1 / 6 + 1 / 2 + 5 / 6),
  count('TOP_AND_Y1', 7), count('TOP_OR_BOTTOM', 14), count('TOP_INNER', 5),
  count('TOP_LEFT', 13), count('TOP_AGAIN', 7), count('LEFT_AGAIN', 7), sum(XYZ, 'X', 'LEFT_AGAIN', 0.0, 'MAX'),
} }

CUBE = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/unit_hexa8.med' }
CUBE = DEFI_GROUP{ reuse = CUBE, MAILLAGE = CUBE, CREA_GROUP_NO = {
  _F{ NOM = 'R1', OPTION = 'ENV_CYLINDRE', POINT = { 0.0, 0.0, 0.0 }, VECT_NORMALE = { 0.0, 0.0, 5.0 }, RAYON = 1.0,
      PRECISION = 1.0e-9 },
  _F{ NOM = 'Z1', OPTION = 'PLAN', POINT = { 0.0, 0.0, 1.0 }, VECT_NORMALE = { 0.0, 0.0, 1.0 }, PRECISION = 1.0e-9 } } }
XYZC = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_GEOM_R', NOM_CHAM = 'GEOMETRIE', MAILLAGE = CUBE }
TEST_RESU{ CHAM_NO = { sum(XYZC, 'Z', 'R1', 2.0), sum(XYZC, 'X', 'R1', 2.0), sum(XYZC, 'Z', 'Z1', 4.0) } }
FIN()
