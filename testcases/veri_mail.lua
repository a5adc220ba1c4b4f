-- LIRE_MAILLAGE VERI_MAIL on a code_aster text mesh with defects (meshes/veri_mail.mail: a node in
-- no cell, an edge written twice, a flat triangle outside the model): read with VERIF='NON' (no
-- warning), without VERI_MAIL (the node in no cell only) and with VERIF='OUI' (every check, as
-- warnings; tests/CMakeLists.txt's log.veri_mail checks them). The study on the two squares is a
-- uniaxial strain: DY = -0.01 on TOP, SIYY = E * -0.01 exactly (NU = 0). Runtime label: fast.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 1.0e6, NU = 0.0 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
for _, veri in ipairs({ 'NON', 'DEFAULT', 'OUI' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'ASTER', FICHIER = 'meshes/veri_mail.mail',
                            VERI_MAIL = veri ~= 'DEFAULT' and _F{ VERIF = veri, APLAT = 1.0e-3 } or nil }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = 'BLOCK', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = 'BLOCK', MATER = MAT } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                                      _F{ GROUP_NO = 'TOP', DY = -0.01 } } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' } }
  TEST_RESU{ RESU = { _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', NOM_CMP = 'SIYY', TYPE_TEST = 'MIN',
                          REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e4, PRECISION = 1.0e-10, LEGENDE = veri },
                      _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', NOM_CMP = 'SIYY', TYPE_TEST = 'MAX',
                          REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e4, PRECISION = 1.0e-10, LEGENDE = veri } } }
end
FIN()
