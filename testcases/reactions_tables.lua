-- Nodal forces and reactions read into tables: CALC_CHAMP FORCE = FORC_NODA/REAC_NODA,
-- POST_RELEVE_T (RESULTANTE, EXTRACTION, MOYENNE_ARITH), TEST_TABLE (FILTRE, TYPE_TEST),
-- table cells read by the deck (TAB['DY'][i]) and IMPR_TABLE (aligned text and CSV).
-- 1. SSNP121 2D geometry glued (QUAD8, D_PLAN, E=2e6, NU=0): CD pushed down by DY = -0.1 m, GH
--    fixed. SIYY = -1e5 Pa over the 2 m width: the reaction resultant on GH is +2e5 N per unit
--    thickness (the body pushes on its support: REAC_NODA = B^T sigma), -2e5 N on CD.
-- 2. Patch blocks (QUAD4 D_PLAN, HEXA8) under a pressure 1e5 Pa on TOP (1 m, 1 m^2), symmetry
--    supports: REAC_NODA on BOTTOM sums to +1e5 N, REAC_NODA on TOP to 0 (the pressure is an
--    applied load), FORC_NODA on TOP to -1e5 N.
-- Reference: analytical (equilibrium). Units SI. Runtime label: fast.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 2 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }

MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/glued2d_quad8.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                               _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, FORCE = { 'FORC_NODA', 'REAC_NODA' } }

-- Resultants on both supports, every step: rows 1..3 are GH (NUME_ORDRE 0, 1, 2), rows 4..6 CD.
RESULT = POST_RELEVE_T{ ACTION = {
  _F{ OPERATION = 'EXTRACTION', INTITULE = 'REAC_GH', RESULTAT = RESU, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'GH',
      RESULTANTE = { 'DX', 'DY' } },
  _F{ OPERATION = 'EXTRACTION', INTITULE = 'REAC_CD', RESULTAT = RESU, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'CD',
      RESULTANTE = { 'DX', 'DY' } },
} }
IMPR_TABLE{ TABLE = RESULT }
local F_GH = RESULT['DY'][3]  -- measured reaction on GH at the last step
print(string.format('reaction on GH: %d rows, %s at NUME_ORDRE %d, DY = %.6e N', #RESULT,
                    RESULT['INTITULE'][3], RESULT['NUME_ORDRE'][3], F_GH))
local function last(intitule)
  return { _F{ NOM_PARA = 'INTITULE', VALE_K = intitule }, _F{ NOM_PARA = 'NUME_ORDRE', VALE_I = 2 } }
end
TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'DY', FILTRE = last('REAC_GH'),
            REFERENCE = 'ANALYTIQUE', VALE_REFE = 2.0e5, PRECISION = 1.0e-10, VALE_CALC = 2.0e5 }
-- Global equilibrium: the reaction on CD is minus the one measured on GH.
TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'DY', FILTRE = last('REAC_CD'),
            REFERENCE = 'ANALYTIQUE', VALE_REFE = -F_GH, PRECISION = 1.0e-12, VALE_CALC = -2.0e5 }
TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'DY', LEGENDE = 'half load at INST 0.5',
            FILTRE = { _F{ NOM_PARA = 'INTITULE', VALE_K = 'REAC_GH' }, _F{ NOM_PARA = 'INST', VALE = 0.5 } },
            REFERENCE = 'ANALYTIQUE', VALE_REFE = 1.0e5, PRECISION = 1.0e-10, VALE_CALC = 1.0e5 }
TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'DX', TYPE_TEST = 'SOMM_ABS', FILTRE = _F{ NOM_PARA = 'NUME_ORDRE', VALE_I = 2 },
            REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, ORDRE_GRANDEUR = 2.0e5, PRECISION = 1.0e-10,
            VALE_CALC = 1.105337762e-10 }
TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'DY', TYPE_TEST = 'MAX', REFERENCE = 'ANALYTIQUE', VALE_REFE = 2.0e5,
            PRECISION = 1.0e-10, VALE_CALC = 2.0e5 }
TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'DY', FILTRE = _F{ NOM_PARA = 'DY', CRIT_COMP = 'MINI' },
            VALE_CALC = -2.0e5 }

-- Node by node on GH at the last step: the nodal reactions add up to SIYY times the 2 m width.
NODES = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'GH', RESULTAT = RESU,
                                    NOM_CHAM = 'REAC_NODA', GROUP_NO = 'GH', NOM_CMP = 'DY', NUME_ORDRE = 2 } }
TEST_TABLE{ TABLE = NODES, NOM_PARA = 'DY', TYPE_TEST = 'SOMM', REFERENCE = 'ANALYTIQUE', VALE_REFE = 1.0e5 * 2.0,
            PRECISION = 1.0e-10, VALE_CALC = 2.0e5 }
-- The QUAD8 corner node at x = 0 takes 1/6 of the force of each of its two 0.5 m edges.
TEST_TABLE{ TABLE = NODES, NOM_PARA = 'DY', FILTRE = _F{ NOM_PARA = 'COOR_X', VALE = 0.0, CRITERE = 'ABSOLU',
                                                          PRECISION = 1.0e-9 },
            REFERENCE = 'ANALYTIQUE', VALE_REFE = 1.0e5 * 0.5 / 3.0, PRECISION = 1.0e-10, VALE_CALC = 1.666666667e4 }
IMPR_TABLE{ TABLE = NODES, FICHIER = 'reactions_gh.csv', SEPARATEUR = ',', NOM_PARA = { 'NOEUD', 'COOR_X', 'DY' },
            FORMAT_R = 'E22.15' }
-- Interface AB: the mean displacement is the exact -0.05 m; its internal forces balance (inner nodes).
MEAN = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'MOYENNE_ARITH', INTITULE = 'AB', RESULTAT = RESU, NOM_CHAM = 'DEPL',
                                   GROUP_NO = 'AB', TOUT_CMP = 'OUI', INST = 1.0 } }
TEST_TABLE{ TABLE = MEAN, NOM_PARA = 'DY', REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.0e-10,
            VALE_CALC = -0.05 }
TEST_RESU{ RESU = _F{ RESULTAT = RESU, NUME_ORDRE = 2, NOM_CHAM = 'FORC_NODA', NOM_CMP = 'DY', TYPE_TEST = 'SOMM',
                      GROUP_NO = 'AB', REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, ORDRE_GRANDEUR = 2.0e5,
                      PRECISION = 1.0e-10, VALE_CALC = 3.819877747e-11 } }

-- Patch blocks under pressure: reactions exclude the applied pressure, internal forces do not.
local P = 1.0e5
for _, case in ipairs({ { 'quad4', 'D_PLAN', 'DY', 'ORIE_PEAU_2D' }, { 'hexa8', '3D', 'DZ', 'ORIE_PEAU_3D' } }) do
  local cell, modelisation, up, orie = case[1], case[2], case[3], case[4]
  local PA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_' .. cell .. '.med' }
  PA = MODI_MAILLAGE{ reuse = PA, MAILLAGE = PA, [orie] = _F{ GROUP_MA = 'TOP' } }
  local PM = AFFE_MODELE{ MAILLAGE = PA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = modelisation } }
  local PC = AFFE_MATERIAU{ MAILLAGE = PA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  local sym = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', [up] = 0.0 } }
  if up == 'DZ' then sym[3] = _F{ GROUP_NO = 'FRONT', DY = 0.0 } end
  local PCH = AFFE_CHAR_MECA{ MODELE = PM, DDL_IMPO = sym, PRES_REP = _F{ GROUP_MA = 'TOP', PRES = P } }
  local PR = STAT_NON_LINE{ MODELE = PM, CHAM_MATER = PC, EXCIT = _F{ CHARGE = PCH },
                            COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
  PR = CALC_CHAMP{ reuse = PR, RESULTAT = PR, FORCE = { 'REAC_NODA', 'FORC_NODA' } }
  local T = POST_RELEVE_T{ ACTION = {
    _F{ OPERATION = 'EXTRACTION', INTITULE = 'BOTTOM', RESULTAT = PR, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'BOTTOM',
        RESULTANTE = up, NUME_ORDRE = 2 },
    _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP', RESULTAT = PR, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'TOP',
        RESULTANTE = up, NUME_ORDRE = 2 },
    _F{ OPERATION = 'EXTRACTION', INTITULE = 'TOP_FORC', RESULTAT = PR, NOM_CHAM = 'FORC_NODA', GROUP_NO = 'TOP',
        RESULTANTE = up, NUME_ORDRE = 2 },
  } }
  local function row(intitule) return _F{ NOM_PARA = 'INTITULE', VALE_K = intitule } end
  TEST_TABLE{ TABLE = T, NOM_PARA = up, FILTRE = row('BOTTOM'), REFERENCE = 'ANALYTIQUE', VALE_REFE = P,
              PRECISION = 1.0e-10, LEGENDE = cell, VALE_CALC = P }
  TEST_TABLE{ TABLE = T, NOM_PARA = up, FILTRE = row('TOP'), REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0,
              ORDRE_GRANDEUR = P, PRECISION = 1.0e-10, LEGENDE = cell,
              VALE_CALC = cell == 'quad4' and -2.182787284e-11 or 1.818989404e-12 }
  TEST_TABLE{ TABLE = T, NOM_PARA = up, FILTRE = row('TOP_FORC'), REFERENCE = 'ANALYTIQUE', VALE_REFE = -P,
              PRECISION = 1.0e-10, LEGENDE = cell, VALE_CALC = -P }
end
FIN()
