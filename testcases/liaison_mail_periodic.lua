-- Periodic conditions by LIAISON_MAIL's TRAN: a block compressed between rigid plates, whose opposite
-- lateral faces are tied to each other (each node of one face follows the cells TRAN away, on the
-- other face), so that it cannot widen: the confined (oedometric) compression.
-- Purpose: AFFE_CHAR_MECA LIAISON_MAIL with TRAN (code_aster's periodic gluing): the slave nodes of
--          LEFT (x = 0) are looked for at x + 1, in the cells along RIGHT; in 3D also those of FRONT
--          (y = 0) at y + 1, a second occurrence, which ELIM_MULT = 'OUI' (the default) rids of the
--          edge nodes the first tied (tying them twice would close a loop of relations: x = 0, y = 0
--          to x = 1, y = 0 to x = 1, y = 1, and to x = 0, y = 1 and back).
-- Meshes: the distorted unit blocks of the patch tests, 3x3 QUAD4 (patch_quad4.med, plane strain) and
--          2x2x2 HEXA8 (patch_hexa8.med); their lateral faces' nodes face each other across the block.
-- Loads: BOTTOM DY (DZ) = 0, TOP DY (DZ) = -0.1; one corner (C00, C000) DX (and DY) = 0 against the
--          rigid sliding the periodic ties leave free. E = 1e6 Pa, NU = 0.3.
-- Reference: analytical, the lateral strains are zero: SIYY (SIZZ) = M EPS, M = E (1 - NU) / ((1 + NU)
--          (1 - 2 NU)) = 1.3461538e6 Pa, EPS = -0.1; the lateral stresses NU / (1 - NU) of it; DX (and
--          DY) = 0 everywhere. The fields are linear: every check at 1e-10 (DX, DY absolute, to 1e-12 m).
-- What we get: stresses within 3.1e-15 of the analytical values (relative), lateral displacements
--          within 1.2e-16 m of zero.
-- Runtime label: fast.
DEBUT()
local E, NU, EPS = 1.0e6, 0.3, -0.1
local M = E * (1.0 - NU) / ((1.0 + NU) * (1.0 - 2.0 * NU))
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

local function check(R, group, cham, cmp, kind, refe, legend)
  local zero = refe == 0.0
  return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = group,
             REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = zero and 1.0e-12 or 1.0e-10,
             CRITERE = zero and 'ABSOLU' or 'RELATIF', LEGENDE = legend }
end

-- Plane strain, 3x3 distorted QUAD4.
MA2 = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_quad4.med' }
MO2 = AFFE_MODELE{ MAILLAGE = MA2, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CM2 = AFFE_MATERIAU{ MAILLAGE = MA2, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH2 = AFFE_CHAR_MECA{ MODELE = MO2,
                      DDL_IMPO = { _F{ GROUP_NO = 'BOTTOM', DY = 0.0 }, _F{ GROUP_NO = 'TOP', DY = EPS },
                                   _F{ GROUP_NO = 'C00', DX = 0.0 } },
                      LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'BLOCK', GROUP_MA_ESCL = 'LEFT', TRAN = { 1.0, 0.0 } } }
R2 = STAT_NON_LINE{ MODELE = MO2, CHAM_MATER = CM2, EXCIT = _F{ CHARGE = CH2 }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                    INCREMENT = _F{ LIST_INST = L_INST } }
R2 = CALC_CHAMP{ reuse = R2, RESULTAT = R2, CONTRAINTE = { 'SIGM_NOEU' } }
TEST_RESU{ RESU = {
  check(R2, 'BLOCK', 'DEPL', 'DX', 'MIN', 0.0, '2D'), check(R2, 'BLOCK', 'DEPL', 'DX', 'MAX', 0.0, '2D'),
  check(R2, 'BLOCK', 'SIGM_NOEU', 'SIYY', 'MIN', M * EPS, '2D'),
  check(R2, 'BLOCK', 'SIGM_NOEU', 'SIYY', 'MAX', M * EPS, '2D'),
  check(R2, 'BLOCK', 'SIGM_NOEU', 'SIXX', 'MIN', NU / (1.0 - NU) * M * EPS, '2D'),
  check(R2, 'BLOCK', 'SIGM_NOEU', 'SIXX', 'MAX', NU / (1.0 - NU) * M * EPS, '2D'),
} }

-- 3D, 2x2x2 distorted HEXA8, periodic in x and in y.
MA3 = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_hexa8.med' }
MO3 = AFFE_MODELE{ MAILLAGE = MA3, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CM3 = AFFE_MATERIAU{ MAILLAGE = MA3, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH3 = AFFE_CHAR_MECA{ MODELE = MO3,
                      DDL_IMPO = { _F{ GROUP_NO = 'BOTTOM', DZ = 0.0 }, _F{ GROUP_NO = 'TOP', DZ = EPS },
                                   _F{ GROUP_NO = 'C000', DX = 0.0, DY = 0.0 } },
                      LIAISON_MAIL = {
                        _F{ GROUP_MA_MAIT = 'BLOCK', GROUP_MA_ESCL = 'LEFT', TRAN = { 1.0, 0.0, 0.0 } },
                        _F{ GROUP_MA_MAIT = 'BLOCK', GROUP_MA_ESCL = 'FRONT', TRAN = { 0.0, 1.0, 0.0 } } } }
for _, elim in ipairs({ 'NON', 'OUI' }) do
  local R3 = STAT_NON_LINE{ MODELE = MO3, CHAM_MATER = CM3, EXCIT = _F{ CHARGE = CH3 },
                            COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                            SOLVEUR = _F{ ELIM_LAGR = elim } }
  R3 = CALC_CHAMP{ reuse = R3, RESULTAT = R3, CONTRAINTE = { 'SIGM_NOEU' } }
  local legend = '3D, ELIM_LAGR ' .. elim
  local lateral = NU / (1.0 - NU) * M * EPS
  TEST_RESU{ RESU = {
    check(R3, 'BLOCK', 'DEPL', 'DX', 'MIN', 0.0, legend), check(R3, 'BLOCK', 'DEPL', 'DX', 'MAX', 0.0, legend),
    check(R3, 'BLOCK', 'DEPL', 'DY', 'MIN', 0.0, legend), check(R3, 'BLOCK', 'DEPL', 'DY', 'MAX', 0.0, legend),
    check(R3, 'BLOCK', 'SIGM_NOEU', 'SIZZ', 'MIN', M * EPS, legend),
    check(R3, 'BLOCK', 'SIGM_NOEU', 'SIZZ', 'MAX', M * EPS, legend),
    check(R3, 'BLOCK', 'SIGM_NOEU', 'SIXX', 'MIN', lateral, legend),
    check(R3, 'BLOCK', 'SIGM_NOEU', 'SIYY', 'MAX', lateral, legend),
  } }
end
FIN()
