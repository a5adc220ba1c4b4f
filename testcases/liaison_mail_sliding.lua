-- Faces glued along their normal only (LIAISON_MAIL, DDL = 'DNOR'): two blocks of different Poisson
-- ratios pressed between frictionless plates, free to widen each by its own amount, so the
-- interface must let them slide on each other.
-- Purpose: AFFE_CHAR_MECA LIAISON_MAIL with DDL = 'DNOR': for each slave node, n . u(node) = n . sum
--          N_a(xi) u_a, n the slave face's normal at the node (from the GROUP_MA_ESCL cells); the
--          tangential components stay free. Solved with a multiplier per relation and with each
--          relation solved for its slave unknown (SOLVEUR ELIM_LAGR = 'NON', 'OUI').
-- Mesh: V1 = [0,1]^3 HEXA8 8x8x2 under V2 = [0,1]^2 x [1,2] HEXA8 4x4x2 (liaison_mail_nested3d.med):
--          slave face SURESC (V1's top), master cells V2's; the slave face is the master face refined
--          twice (nested). Then the same in plane strain: PLAQUE1 = [-1,1]x[0,1] QUAD4 16x16 (NU2,
--          E2; slave edge AB) on PLAQUE2 = [-1,1]x[-1,0] QUAD4 8x8 (NU1, E1; master cells)
--          (liaison_mail_nested2d.med), GH DY = 0, CD DY = -0.1, G (1,-1) and D (-1,1) DX = 0: the
--          normals of SEG2 cells.
-- Loads: ENCAST (z = 0) DZ = 0, SURCHA (z = 2) DZ = -0.1; against the rigid motions each block keeps
--          in its plane, N1 (0,0,0) and N294 (0,0,2) DX = DY = 0, N34 (1,0,0) and N303 (1,0,2) DY = 0.
--          V1: E1 = 6e6 Pa, NU1 = 0.3; V2: E2 = 2e6 Pa, NU2 = 0.2.
-- Reference: analytical, each block in uniaxial compression p = 0.1 / (1/E1 + 1/E2) = 1.5e5 Pa:
--          SIZZ = -p and SIXX = SIYY = 0 everywhere; DZ = -p/E1 = -0.025 m on the interface (both
--          sides); each block widens by NU p / E: DX = NU1 p / E1 x = 0.0075 x m in V1 and NU2 p / E2 x
--          = 0.015 x m in V2, so at x = 1 the two faces are 0.0075 m apart. Linear fields: checks at
--          1e-10 (SIXX, SIYY absolute, to 1e-5 Pa against p = 1.5e5 Pa). Glued in every component the
--          faces could not slide, and the blocks would not be in uniaxial compression.
--          Plane strain: SIYY = -p, SIXX = 0, p = 0.1 / ((1 - NU1^2)/E1 + (1 - NU2^2)/E2), DY = -(1 - NU1^2)
--          p/E1 on the interface, DX = NU2 (1 + NU2) p/E2 (x + 1) above, NU1 (1 + NU1) p/E1 (x - 1) below.
-- What we get: within 1.4e-13 of the analytical values (relative), SIXX and SIYY within 3.2e-8 Pa of zero.
-- Runtime label: fast.
DEBUT()
local E1, NU1, E2, NU2 = 6.0e6, 0.3, 2.0e6, 0.2
local p = 0.1 / (1.0 / E1 + 1.0 / E2)
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/liaison_mail_nested3d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
M1 = DEFI_MATERIAU{ ELAS = _F{ E = E1, NU = NU1 } }
M2 = DEFI_MATERIAU{ ELAS = _F{ E = E2, NU = NU2 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'V1', MATER = M1 },
                                           _F{ GROUP_MA = 'V2', MATER = M2 } } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DZ = 0.0 }, _F{ GROUP_NO = 'SURCHA', DZ = -0.1 },
                                  _F{ NOEUD = { 'N1', 'N294' }, DX = 0.0, DY = 0.0 },
                                  _F{ NOEUD = { 'N34', 'N303' }, DY = 0.0 } },
                     LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'V2', GROUP_MA_ESCL = 'SURESC', DDL = 'DNOR' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- A check against the analytical value: relative at 1e-10, absolute at 1e-5 (Pa or m) for zero.
local function check(R, legend, cham, cmp, kind, group, refe)
  local zero = refe == 0.0
  return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = group,
             REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = zero and 1.0e-5 or 1.0e-10,
             CRITERE = zero and 'ABSOLU' or 'RELATIF', LEGENDE = legend }
end

for _, elim in ipairs({ 'NON', 'OUI' }) do
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                           SOLVEUR = _F{ ELIM_LAGR = elim } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' } }
  local function t(...) return check(R, 'ELIM_LAGR ' .. elim, ...) end
  TEST_RESU{ RESU = {
    t('DEPL', 'DZ', 'MIN', 'SURESC', -p / E1), t('DEPL', 'DZ', 'MAX', 'SURESC', -p / E1),
    t('DEPL', 'DZ', 'MIN', 'SURMAI', -p / E1), t('DEPL', 'DZ', 'MAX', 'SURMAI', -p / E1),
    t('DEPL', 'DX', 'MAX', 'SURESC', NU1 * p / E1), t('DEPL', 'DX', 'MAX', 'SURMAI', NU2 * p / E2),
    t('DEPL', 'DY', 'MAX', 'SURESC', NU1 * p / E1), t('DEPL', 'DY', 'MAX', 'SURMAI', NU2 * p / E2),
    t('SIGM_NOEU', 'SIZZ', 'MIN', 'V1', -p), t('SIGM_NOEU', 'SIZZ', 'MAX', 'V2', -p),
    t('SIGM_NOEU', 'SIXX', 'MIN', 'V1', 0.0), t('SIGM_NOEU', 'SIXX', 'MAX', 'V2', 0.0),
    t('SIGM_NOEU', 'SIYY', 'MIN', 'V2', 0.0), t('SIGM_NOEU', 'SIYY', 'MAX', 'V1', 0.0),
  } }
end

-- Plane strain: the normals of the slave edge's SEG2 cells.
MA2 = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/liaison_mail_nested2d.med' }
MO2 = AFFE_MODELE{ MAILLAGE = MA2, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CM2 = AFFE_MATERIAU{ MAILLAGE = MA2, AFFE = { _F{ GROUP_MA = 'PLAQUE2', MATER = M1 },
                                              _F{ GROUP_MA = 'PLAQUE1', MATER = M2 } } }
CH2 = AFFE_CHAR_MECA{ MODELE = MO2,
                      DDL_IMPO = { _F{ GROUP_NO = 'GH', DY = 0.0 }, _F{ GROUP_NO = 'CD', DY = -0.1 },
                                   _F{ GROUP_NO = { 'G', 'D' }, DX = 0.0 } },
                      LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'PLAQUE2', GROUP_MA_ESCL = 'AB', DDL = 'DNOR' } }
R2 = STAT_NON_LINE{ MODELE = MO2, CHAM_MATER = CM2, EXCIT = _F{ CHARGE = CH2 }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                    INCREMENT = _F{ LIST_INST = L_INST } }
R2 = CALC_CHAMP{ reuse = R2, RESULTAT = R2, CONTRAINTE = { 'SIGM_NOEU' } }
local p2 = 0.1 / ((1.0 - NU1 ^ 2) / E1 + (1.0 - NU2 ^ 2) / E2)
local function t2(...) return check(R2, 'plane strain', ...) end
TEST_RESU{ RESU = {
  t2('DEPL', 'DY', 'MIN', 'AB', -(1.0 - NU1 ^ 2) * p2 / E1), t2('DEPL', 'DY', 'MAX', 'EF', -(1.0 - NU1 ^ 2) * p2 / E1),
  t2('DEPL', 'DX', 'MAX', 'AB', 2.0 * NU2 * (1.0 + NU2) * p2 / E2),
  t2('DEPL', 'DX', 'MIN', 'EF', -2.0 * NU1 * (1.0 + NU1) * p2 / E1),          -- G = (1, -1) held
  t2('SIGM_NOEU', 'SIYY', 'MIN', 'PLAQUE1', -p2), t2('SIGM_NOEU', 'SIYY', 'MAX', 'PLAQUE2', -p2),
  t2('SIGM_NOEU', 'SIXX', 'MIN', 'PLAQUE1', 0.0), t2('SIGM_NOEU', 'SIXX', 'MAX', 'PLAQUE2', 0.0),
} }
FIN()
