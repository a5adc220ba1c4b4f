-- Meshes in code_aster's text format (LIRE_MAILLAGE FORMAT='ASTER', .mail files written by
-- lunaster-meshgen from the same blocks as the MED files): each study runs on the .mail mesh and
-- on the MED mesh it was written from, and both must give the same values.
-- 1. SSNP121 A (ssnp121a.lua's study, contact between non-matching QUAD4 blocks, groups read from
--    GROUP_MA / GROUP_NO blocks): the VALE_CALC values are ssnp121a.lua's, recorded on the MED mesh;
--    analytical LAGS_C = -1e5 Pa, DY = -0.05 m (code_aster's 1 %).
-- 2. 3D patch tests of the quadratic cells whose node order code_aster lists differently from MED
--    (HEXA20, PENTA15, TETRA10; distorted blocks, uniaxial strain along z, imposed DZ on TOP):
--    Hooke's law exactly, to round-off (1e-10), on both meshes.
-- Units SI. Runtime label: fast, contact.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
local calc = {  -- ssnp121a.lua's
  A = { DY = -4.999669690478e-02, LAGS_C = -1.000795227287e+05 },
  O = { DY = -4.997830886910e-02, LAGS_C = -1.003593668221e+05 },
  B = { DY = -4.999669690478e-02, LAGS_C = -1.000795227287e+05 },
}
for _, mesh in ipairs({ { 'MED', 'ssnp121a.med' }, { 'ASTER', 'meshes/ssnp121a.mail' } }) do
  local MA = LIRE_MAILLAGE{ FORMAT = mesh[1], FICHIER = mesh[2] }
  local MO = AFFE_MODELE{ MAILLAGE = MA,
                          AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
  local CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
  local CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                               DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                            _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
  local CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                             ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                             REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
                             ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON',
                                        ORDRE_INT = 4, COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
  local RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                              EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                              COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                              CONVERGENCE = _F{ RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 } }
  local checks = {}
  for _, point in ipairs({ 'A', 'O', 'B' }) do
    for _, c in ipairs({ { 'DY', -0.05 }, { 'LAGS_C', -1.0e5 } }) do  -- in this order: the checks' order is compared
      local cmp, refe = c[1], c[2]
      checks[#checks + 1] = _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = cmp,
                                VALE_CALC = calc[point][cmp], REFERENCE = 'ANALYTIQUE', VALE_REFE = refe,
                                PRECISION = 1.0e-2, LEGENDE = 'SSNP121 A, ' .. mesh[2] }
    end
  end
  TEST_RESU{ RESU = checks }
end

local E, NU, EPS = 2.0e6, 0.3, -0.01
local MAT3 = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
for _, cell in ipairs({ 'hexa20', 'penta15', 'tetra10' }) do
  for _, format in ipairs({ 'MED', 'ASTER' }) do
    local file = 'meshes/patch_' .. cell .. (format == 'MED' and '.med' or '.mail')
    local MA = LIRE_MAILLAGE{ FORMAT = format, FICHIER = file }
    local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT3 } }
    local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
    local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'FRONT', DY = 0.0 },
                                                        _F{ GROUP_NO = 'BOTTOM', DZ = 0.0 }, _F{ GROUP_NO = 'TOP', DZ = EPS } } }
    local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                             COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' } }
    local function t(cham, cmp, kind, refe, group)
      return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = group,
                 REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10, LEGENDE = file }
    end
    TEST_RESU{ RESU = { t('SIGM_NOEU', 'SIZZ', 'MIN', E * EPS), t('SIGM_NOEU', 'SIZZ', 'MAX', E * EPS),
                        t('DEPL', 'DX', 'MIN', -NU * EPS, 'RIGHT'), t('DEPL', 'DX', 'MAX', -NU * EPS, 'RIGHT') } }
  end
end
FIN()
