-- FORCE_FACE against PRES_REP: the unit cube (distorted patch meshes, HEXA8, HEXA20, TETRA10) in
-- uniaxial compression, symmetry supports (DX = 0 on LEFT, DY = 0 on FRONT, DZ = 0 on BOTTOM):
--   TOP loaded by PRES = P (pushing against the outward normal +z), or by FORCE_FACE FZ = -P
--   (the same traction, given by its components: the sign is that of the force, not of a normal).
--   sigma_zz = -P, u_z(C111) = -P / E, u_x(C111) = u_y(C111) = NU P / E; base reaction +P.
-- A uniform stress is exact on every one of these meshes and a uniform traction on a plane face
-- integrates exactly: each check holds to round-off, tolerance 1e-12 (1e-10 for the reaction,
-- a sum of nodal forces); and FORCE_FACE's displacement equals PRES_REP's to 1e-12.
-- No VALE_CALC: every check is analytical at the tolerance an exact method allows.
-- Reference: analytical. Units SI. Runtime label: fast.
DEBUT()
local E, NU, P = 2.0e11, 0.3, 1.0e8
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
for _, cell in ipairs({ 'hexa8', 'hexa20', 'tetra10' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_' .. cell .. '.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  local BC = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_MA = 'LEFT', DX = 0.0 },
                                                      _F{ GROUP_MA = 'FRONT', DY = 0.0 },
                                                      _F{ GROUP_MA = 'BOTTOM', DZ = 0.0 } } }
  local loads = {
    PRES_REP = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'TOP', PRES = P } },
    FORCE_FACE = AFFE_CHAR_MECA{ MODELE = MO, FORCE_FACE = _F{ GROUP_MA = 'TOP', FZ = -P } },
  }
  local dz, tabs = {}, {}
  for _, kind in ipairs({ 'PRES_REP', 'FORCE_FACE' }) do
    local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = { _F{ CHARGE = BC }, _F{ CHARGE = loads[kind] } },
                             COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, FORCE = 'REAC_NODA' }
    local legend = cell .. ' ' .. kind
    local function t(cmp, refe)
      return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = cmp, GROUP_NO = 'C111', LEGENDE = legend,
                 REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-12 }
    end
    TEST_RESU{ RESU = { t('DZ', -P / E), t('DX', NU * P / E), t('DY', NU * P / E) } }
    local T = POST_RELEVE_T{ ACTION = {
      _F{ OPERATION = 'EXTRACTION', INTITULE = 'BASE', RESULTAT = R, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'BOTTOM',
          RESULTANTE = 'DZ', NUME_ORDRE = 1 },
      _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = R, NOM_CHAM = 'DEPL', GROUP_NO = 'C111',
          NOM_CMP = 'DZ', NUME_ORDRE = 1 } } }
    TEST_TABLE{ TABLE = T, NOM_PARA = 'DZ', FILTRE = _F{ NOM_PARA = 'INTITULE', VALE_K = 'BASE' }, LEGENDE = legend,
                REFERENCE = 'ANALYTIQUE', VALE_REFE = P, PRECISION = 1.0e-10 }
    dz[kind], tabs[kind] = T['DZ'][2], T
  end
  -- The two loads give the same displacement, to round-off.
  TEST_TABLE{ TABLE = tabs.FORCE_FACE, NOM_PARA = 'DZ', FILTRE = _F{ NOM_PARA = 'INTITULE', VALE_K = 'TOP' },
              LEGENDE = cell .. ' FORCE_FACE = PRES_REP', REFERENCE = 'ANALYTIQUE', VALE_REFE = dz.PRES_REP,
              PRECISION = 1.0e-12 }
end
FIN()
