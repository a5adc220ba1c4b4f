-- TEST_RESU and TEST_TABLE reference forms that code_aster's contact decks use: VALE_ABS
-- (absolute values compared), PARA = 'INST' (a parameter of the result instead of a field's
-- component), VALE_CALC_I / VALE_REFE_I (an integer column of a table), and a result's field per
-- cell tested at a cell's node (MAILLE, NOEUD) or integration point (MAILLE, POINT).
-- Scene: SSNP121's 2D geometry glued (QUAD8, D_PLAN, E = 2e6, NU = 0): CD pushed down by
-- DY = -0.1 m at INST 0.5 and 1; GH fixed.
-- Reference: analytical. DY on CD is -0.1 m at INST 1 (|DY| = 0.1); SIYY = -1e5 Pa everywhere,
-- over the 2 m width, so REAC_NODA's resultant DY is +2e5 N on GH and -2e5 N on CD (|.| = 2e5 on
-- both); the result stores NUME_ORDRE 0, 1, 2 at INST 0, 0.5, 1. Units SI. Runtime label: fast.
-- errors/check_vale_abs_sign.lua shows the same references without VALE_ABS failing.
DEBUT()
-- VMIS_ISOT_LINE far below yield: Hooke's law, with the stresses at integration points (SIEF_ELGA)
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 }, ECRO_LINE = _F{ D_SIGM_EPSI = 1.0e5, SY = 1.0e9 } }
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/glued2d_quad8.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
-- GH held, CD pushed down by 0.1 at every instant (no FONC_MULT: the load's multiplier is 1)
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 },
                                               _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 } } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                      COMPORTEMENT = _F{ RELATION = 'VMIS_ISOT_LINE', TOUT = 'OUI' },
                      INCREMENT = _F{ LIST_INST = DEFI_LIST_REEL{ VALE = { 0.0, 0.5, 1.0 } } } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, FORCE = 'REAC_NODA', CONTRAINTE = 'SIGM_ELNO' }
U = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_DEPL_R', NOM_CHAM = 'DEPL', RESULTAT = RESU, INST = 1.0 }
SG = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'ELGA_SIEF_R', NOM_CHAM = 'SIEF_ELGA', RESULTAT = RESU, INST = 1.0 }

TEST_RESU{
  RESU = {
    -- |DY| on CD: the push's magnitude, whatever the sign convention
    _F{ RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'DEPL', NOM_CMP = 'DY', GROUP_NO = 'CD', TYPE_TEST = 'MIN',
        VALE_ABS = 'OUI', REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.1, PRECISION = 1.0e-12, VALE_CALC = 0.1 },
    -- a negative reference is compared by its absolute value too
    _F{ RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'DEPL', NOM_CMP = 'DY', GROUP_NO = 'CD', TYPE_TEST = 'MAX',
        VALE_ABS = 'OUI', REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1, PRECISION = 1.0e-12, VALE_CALC = -0.1 },
    -- the result's parameter INST at a NUME_ORDRE
    _F{ RESULTAT = RESU, NUME_ORDRE = 1, PARA = 'INST', REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.5,
        PRECISION = 1.0e-14, CRITERE = 'ABSOLU', VALE_CALC = 0.5 },
    _F{ RESULTAT = RESU, INST = 1.0, PARA = 'INST', REFERENCE = 'ANALYTIQUE', VALE_REFE = 1.0, PRECISION = 1.0e-14,
        VALE_CALC = 1.0 },
    -- a result's fields per cell: at a node of a cell (ELNO), at an integration point (ELGA)
    _F{ RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'SIGM_ELNO', NOM_CMP = 'SIYY', MAILLE = 'M33', NOEUD = 'N3',
        REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-9, VALE_CALC = -1.0e5 },
    _F{ RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'SIEF_ELGA', NOM_CMP = 'SIYY', MAILLE = 'M34', POINT = 4,
        REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-9, VALE_CALC = -1.0e5 },
  },
  CHAM_ELEM = _F{ CHAM_GD = SG, NOM_CMP = 'SIYY', MAILLE = 'M35', POINT = 9, VALE_ABS = 'OUI',
                  REFERENCE = 'ANALYTIQUE', VALE_REFE = 1.0e5, PRECISION = 1.0e-9, VALE_CALC = 1.0e5 },
  -- VALE_ABS = 'NON', the default: the signed sum over CD's 9 nodes (4 QUAD8 edges)
  CHAM_NO = _F{ CHAM_GD = U, NOM_CMP = 'DY', GROUP_NO = 'CD', TYPE_TEST = 'SOMM', VALE_ABS = 'NON',
                REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1 * 9, PRECISION = 1.0e-12, VALE_CALC = -0.9 },
}

RESULT = POST_RELEVE_T{ ACTION = {
  _F{ OPERATION = 'EXTRACTION', INTITULE = 'REAC_GH', RESULTAT = RESU, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'GH',
      RESULTANTE = 'DY' },
  _F{ OPERATION = 'EXTRACTION', INTITULE = 'REAC_CD', RESULTAT = RESU, NOM_CHAM = 'REAC_NODA', GROUP_NO = 'CD',
      RESULTANTE = 'DY' },
} }
local function at_end(intitule)
  return { _F{ NOM_PARA = 'INTITULE', VALE_K = intitule }, _F{ NOM_PARA = 'INST', VALE = 1.0 } }
end
-- The same magnitude on both supports, of opposite signs.
for _, support in ipairs({ 'REAC_GH', 'REAC_CD' }) do
  TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'DY', FILTRE = at_end(support), VALE_ABS = 'OUI', LEGENDE = support,
              REFERENCE = 'ANALYTIQUE', VALE_REFE = 2.0e5, PRECISION = 1.0e-10, VALE_CALC = 2.0e5 }
end
-- NUME_ORDRE, an integer column: the last step is the second after the initial state.
TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'NUME_ORDRE', FILTRE = at_end('REAC_CD'),
            REFERENCE = 'ANALYTIQUE', VALE_REFE_I = 2, VALE_CALC_I = 2 }
TEST_TABLE{ TABLE = RESULT, NOM_PARA = 'NUME_ORDRE', TYPE_TEST = 'SOMM',
            FILTRE = _F{ NOM_PARA = 'INTITULE', VALE_K = 'REAC_GH' }, CRITERE = 'ABSOLU',
            REFERENCE = 'ANALYTIQUE', VALE_REFE_I = 0 + 1 + 2, PRECISION = 0.0, VALE_CALC_I = 3, TOLE_MACHINE = 0.0 }
FIN()
