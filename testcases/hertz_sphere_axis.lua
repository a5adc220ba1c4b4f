-- Hertz point contact in AXIS (x = r, y = axis): an elastic sphere (radius R = 1 m) pressed on an
-- elastic block, frictionless, mortar contact with Lagrange multipliers (DEFI_CONT). The quarter
-- disc BALL (x >= 0) centred at (0, R) touches the block BLOCK = [0,1] x [-1,0] (a cylinder of
-- radius 1 m and height 1 m) at the origin; a pressure Q on the flat top BALL_TOP (y = R); the
-- block's bottom is fixed; DX = 0 on the axis. The same scene as hertz_sphere_3d.lua in 2D.
-- Mesh: `lunaster-meshgen --hertz quad8:160 --grading 1.5` (tools/make_meshes.sh), QUAD8 cells of
-- h0 = R/160 = a/16 near O growing by about 1.5 per layer (378 nodes): 0.05 s, 27 MB peak
-- (tests/bench/README.md).
-- The force is measured, not assumed: F = 2 pi x (resultant DY of REAC_NODA on BLOCK_BOTTOM), as
-- AXIS reactions are per radian; it matches Q pi R^2 to round-off (checked below). Hertz from the
-- measured F (two identical bodies, E = 1e9 Pa, nu = 0.3): 1/E* = 2 (1 - nu^2) / E,
-- a = (3 F R / (4 E*))^(1/3) = 0.1 m (Q chosen for it: a/R = 0.1, the block is 10 a wide and
-- deep), p0 = 3 F / (2 pi a^2), p(r) = p0 sqrt(1 - r^2/a^2).
-- The node of BLOCK_TOP on the axis carries no multiplier: with the AXIS measure r dl the
-- integral of r N over its cell is zero, so its dual function is zero (the cell's other two stay
-- biorthogonal to it). p0 is checked at the next node, the mid-side at r = h0/2 = a/32
-- (p = 0.9995 p0 there; the check uses p(r)).
-- Error budget, measured with this deck (p at r = a/32 against Hertz): -0.43 % on this mesh;
-- blocks of 2 x 2 and 4 x 4 give +0.11 % and -0.45 %; the uniform `--hertz quad8:80` (h0 = a/8,
-- 20000 nodes) gives +0.13 % at r = a/16. On `quad8:20 --grading 1.5 --refine 2` and `4` the
-- node next to the axis reads 0.7 % and 0.5 % off p(r) (until 2026-11-29 the axis cell was
-- dropped there and its neighbour carried three times p0). Checked: the measured force, p
-- at r = a/32 (N211) to 0.5 %, p at r = 0.514 a (N271, the node nearest a/2) to 2 %, and the edge
-- of the contact between r = 0.916 a (N282, in contact) and r = 1.14 a (N299, open).
DEBUT()
local R, E, NU, A_TARGET = 1.0, 1.0e9, 0.3, 0.1
local E_STAR = 1.0 / (2.0 * (1.0 - NU ^ 2) / E)
local F_APPLIED = 4.0 * E_STAR * A_TARGET ^ 3 / (3.0 * R)  -- the force giving a = A_TARGET
local Q = F_APPLIED / (math.pi * R ^ 2)
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CHA = AFFE_CHAR_MECA{ MODELE = MO,
                      DDL_IMPO = { _F{ GROUP_MA = { 'AXIS_BALL', 'AXIS_BLOCK' }, DX = 0.0 },
                                   _F{ GROUP_MA = 'BLOCK_BOTTOM', DX = 0.0, DY = 0.0 } },
                      PRES_REP = _F{ GROUP_MA = 'BALL_TOP', PRES = Q } }
-- The sphere is held vertically by the contact alone: CONTACT_INIT='OUI' starts with every
-- slave node in contact, and the active set then opens those in tension.
CONT = DEFI_CONT{ MODELE = MO, REAC_GEOM = 'SANS',
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'BLOCK_TOP', GROUP_MA_MAIT = 'BALL_SURF',
                             CONTACT_INIT = 'OUI' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                      CONVERGENCE = _F{ ITER_GLOB_MAXI = 40 } }

-- The force from the reactions (per radian in AXIS: times 2 pi for the whole sphere).
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, FORCE = 'REAC_NODA' }
REAC = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'BOTTOM', RESULTAT = RESU, NOM_CHAM = 'REAC_NODA',
                                   GROUP_NO = 'BLOCK_BOTTOM', RESULTANTE = 'DY', NUME_ORDRE = 1 } }
-- calc: lunaster's own value from a real run (VALE_CALC, non-regression, relative 1e-6).
TEST_TABLE{ TABLE = REAC, NOM_PARA = 'DY', REFERENCE = 'ANALYTIQUE', VALE_REFE = F_APPLIED / (2.0 * math.pi),
            PRECISION = 1.0e-9, VALE_CALC = 1.165970279e+05 }
local F = 2.0 * math.pi * REAC['DY'][1]
local A = (3.0 * F * R / (4.0 * E_STAR)) ^ (1.0 / 3.0)
local P0 = 3.0 * F / (2.0 * math.pi * A ^ 2)

local function pressure(node, calc, r, precision)
  return _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'LAGS_C', NOEUD = node,
             VALE_CALC = calc, REFERENCE = 'ANALYTIQUE', VALE_REFE = -P0 * math.sqrt(1.0 - (r / A) ^ 2),
             PRECISION = precision }
end
local function status(node, calc, refe)
  return _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'CONT_NOEU', NOM_CMP = 'CONT', NOEUD = node, VALE_CALC = calc,
             REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, CRITERE = 'ABSOLU', PRECISION = 0.0 }
end
TEST_RESU{ RESU = {
  pressure('N211', -3.481232207e+07, 3.125e-3, 5.0e-3),
  pressure('N271', -2.965091028e+07, 5.140405132471349e-2, 2.0e-2),
  status('N282', 1, 1),
  status('N299', 0, 0),
} }
FIN()
