-- The SSNP121 3D geometry (two unit cubes stacked) with the interface glued (shared nodes): no
-- contact, so HEXA8 and HEXA20 meshes must reproduce the exact solution to round-off.
-- ENCAST (z=0): DX=DY=DZ=0; SURCHA (z=2): DX=DY=0, DZ=-0.1; E=2e6, NU=0.
-- Reference: analytical SIZZ = -1e5 Pa everywhere, DZ = -0.05 m on the interface. Runtime label: fast.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
for _, cell in ipairs({ 'hexa8', 'hexa20' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/glued3d_' .. cell .. '.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO,
                             DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                          _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
  local function t(cham, cmp, kind, refe, group)
    return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = group,
               REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10, LEGENDE = cell }
  end
  TEST_RESU{ RESU = {
    t('SIGM_NOEU', 'SIZZ', 'MIN', -1.0e5), t('SIGM_NOEU', 'SIZZ', 'MAX', -1.0e5),
    t('DEPL', 'DZ', 'MIN', -0.05, 'SURESC'), t('DEPL', 'DZ', 'MAX', -0.05, 'SURESC'),
  } }
end
FIN()
