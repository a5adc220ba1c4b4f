-- Element patch tests in 3D: a distorted unit cube of each element type (HEXA8, HEXA20, PENTA6,
-- PENTA15, TETRA4, TETRA10) under uniform uniaxial stress along z, loaded by an imposed displacement
-- or by a pressure (PRES_REP on TOP). Symmetry conditions on LEFT (x=0, DX=0), FRONT (y=0, DY=0)
-- and BOTTOM (z=0, DZ=0) leave a uniform exact field that every element must reproduce to
-- round-off (1e-10). Reference: analytical (Hooke's law). Units SI. Runtime label: fast.
DEBUT()
local E, NU, EPS, P = 2.0e6, 0.3, -0.01, 1.0e4
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

for _, cell in ipairs({ 'hexa8', 'hexa20', 'penta6', 'penta15', 'tetra4', 'tetra10' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_' .. cell .. '.med' }
  MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_3D = _F{ GROUP_MA = 'TOP' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
  for _, loading in ipairs({ 'DEPL', 'PRES' }) do
    local szz = loading == 'PRES' and -P or E * EPS
    local ezz, exx = szz / E, -NU * szz / E
    local sym = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'FRONT', DY = 0.0 },
                  _F{ GROUP_NO = 'BOTTOM', DZ = 0.0 } }
    local CH
    if loading == 'DEPL' then
      sym[#sym + 1] = _F{ GROUP_NO = 'TOP', DZ = ezz }
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
                 LEGENDE = cell .. ' ' .. loading }
    end
    TEST_RESU{ RESU = {
      t('SIGM_NOEU', 'SIZZ', 'MIN', szz), t('SIGM_NOEU', 'SIZZ', 'MAX', szz),
      t('DEPL', 'DZ', 'MIN', ezz, 'TOP'), t('DEPL', 'DZ', 'MAX', ezz, 'TOP'),
      t('DEPL', 'DX', 'MIN', exx, 'RIGHT'), t('DEPL', 'DX', 'MAX', exx, 'RIGHT'),
    } }
  end
end
FIN()
