-- The SSNP121 2D geometry with the interface glued (both blocks share the interface nodes):
-- no contact, so the exact solution must be reproduced to round-off by QUAD4 and QUAD8 meshes.
-- Upper block [-1,1]x[0,1], lower block [-1,1]x[-1,0]; CD: DX=0, DY=-0.1; GH: DX=DY=0; E=2e6, NU=0.
-- Reference: analytical strain -0.05, SIYY = -1e5 Pa everywhere, DY = -0.05 m on the interface,
-- equivalent stresses VMIS = TRESCA = 1e5 Pa. Also writes the interface values as a text table.
-- Runtime label: fast.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
for _, cell in ipairs({ 'quad4', 'quad8' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/glued2d_' .. cell .. '.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA,
                          AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO,
                             DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                          _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' },
                  CRITERES = { 'SIEQ_ELNO', 'SIEQ_NOEU' } }
  IMPR_RESU{ FORMAT = 'RESULTAT', FICHIER = 'glued_' .. cell .. '_AB.resu',
             RESU = _F{ RESULTAT = R, NOM_CHAM = { 'DEPL', 'SIGM_NOEU' }, GROUP_NO = 'AB' } }
  local function t(cham, cmp, kind, refe, group)
    return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = group,
               REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10, LEGENDE = cell }
  end
  TEST_RESU{ RESU = {
    t('SIGM_NOEU', 'SIYY', 'MIN', -1.0e5), t('SIGM_NOEU', 'SIYY', 'MAX', -1.0e5),
    t('DEPL', 'DY', 'MIN', -0.05, 'AB'), t('DEPL', 'DY', 'MAX', -0.05, 'AB'),
    -- uniaxial, NU = 0: von Mises = |SIYY|, Tresca = |SIYY|, PRIN_1 = SIYY (ascending order)
    t('SIEQ_NOEU', 'VMIS', 'MIN', 1.0e5), t('SIEQ_NOEU', 'VMIS', 'MAX', 1.0e5),
    t('SIEQ_NOEU', 'TRESCA', 'MAX', 1.0e5), t('SIEQ_NOEU', 'PRIN_1', 'MIN', -1.0e5),
  } }
end
FIN()
