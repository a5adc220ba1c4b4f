-- Element patch tests in 2D: a distorted unit block of each element type (QUAD4, QUAD8, TRIA3, TRIA6)
-- under uniform uniaxial stress, in plane strain (D_PLAN) and plane stress (C_PLAN), loaded by an
-- imposed displacement or by a pressure (PRES_REP). Symmetry conditions on LEFT (DX=0) and BOTTOM
-- (DY=0) leave a uniform exact field that every element must reproduce to round-off (1e-10).
-- Reference: analytical (Hooke's law). Units SI. Runtime label: fast.
DEBUT()
local E, NU, EPS, P = 2.0e6, 0.3, -0.01, 1.0e4
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- Exact uniaxial solution: (eps_yy, eps_xx, sigma_yy) for a given stress or strain.
local function exact(modelisation, syy)
  if modelisation == 'D_PLAN' then
    return (1 - NU * NU) * syy / E, -NU * (1 + NU) * syy / E, syy
  end
  return syy / E, -NU * syy / E, syy
end

for _, cell in ipairs({ 'quad4', 'quad8', 'tria3', 'tria6' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_' .. cell .. '.med' }
  MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = 'TOP' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  for _, modelisation in ipairs({ 'D_PLAN', 'C_PLAN' }) do
    local MO = AFFE_MODELE{ MAILLAGE = MA,
                            AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = modelisation } }
    for _, loading in ipairs({ 'DEPL', 'PRES' }) do
      local syy = loading == 'PRES' and -P or (modelisation == 'D_PLAN' and E * EPS / (1 - NU * NU) or E * EPS)
      local eyy, exx = exact(modelisation, syy)
      local sym = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 } }
      local CH
      if loading == 'DEPL' then
        sym[#sym + 1] = _F{ GROUP_NO = 'TOP', DY = eyy }
        CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = sym }
      else
        CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = sym, PRES_REP = _F{ GROUP_MA = 'TOP', PRES = P } }
      end
      local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                               COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
      R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
      local function t(cham, cmp, kind, refe, group)
        return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind,
                   GROUP_NO = group, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10,
                   LEGENDE = cell .. ' ' .. modelisation .. ' ' .. loading }
      end
      TEST_RESU{ RESU = {
        t('SIGM_NOEU', 'SIYY', 'MIN', syy), t('SIGM_NOEU', 'SIYY', 'MAX', syy),
        t('DEPL', 'DY', 'MIN', eyy, 'TOP'), t('DEPL', 'DY', 'MAX', eyy, 'TOP'),
        t('DEPL', 'DX', 'MIN', exx, 'RIGHT'), t('DEPL', 'DX', 'MAX', exx, 'RIGHT'),
      } }
    end
  end
end
FIN()
