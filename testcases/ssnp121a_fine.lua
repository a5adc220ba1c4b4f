-- SSNP121 A on a finer mesh: 48 x 48 QUAD4 (upper block, slave edge AB) over 44 x 44 (lower block,
-- master edge EF), CONTINUE, SIMPSON ORDRE_INT=4, COEF_CONT=1000, CONTACT_INIT='NON' as in SSNP121 A.
-- Purpose: the contact passes solved on the elastic factorisation kept for the run. With
--          SOLVEUR METHODE='AUTO' (the default) the 237 equations of the contact surfaces are
--          ordered last in one CHOLMOD factorisation of the elastic stiffness, and each contact pass
--          factorises only their Schur complement; METHODE='MUMPS' factorises the whole indefinite
--          system at every pass. Both must give the analytical answer, and the same numbers.
-- Reference: analytical, uniform strain -0.05 in both blocks: LAGS_C = -1e5 Pa on AB, DY = -0.05 m
--            on AB. Units SI. Runtime label: fast, contact.
-- Mesh: lunaster-meshgen --upper quad4:48 --lower quad4:44 (tools/make_meshes.sh).
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/ssnp121a_fine.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON',
                                ORDRE_INT = 4, COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- VALE_CALC: lunaster's own values from a real run (non-regression), the same for both solvers.
-- LAGS_C is 0.36 % off at its worst (the node-to-segment error of SSNP121 A, whose tolerance is 1 %).
local results = {}
for _, methode in ipairs({ 'AUTO', 'MUMPS' }) do
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA1 },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                           SOLVEUR = _F{ METHODE = methode },
                           CONVERGENCE = _F{ RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 } }
  results[methode] = R
  TEST_RESU{ RESU = {
    _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'AB', NOM_CMP = 'LAGS_C', TYPE_TEST = 'MIN',
        REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 5.0e-3, LEGENDE = methode,
        VALE_CALC = -1.003595540807e+05 },
    _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'AB', NOM_CMP = 'LAGS_C', TYPE_TEST = 'MAX',
        REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 5.0e-3, LEGENDE = methode,
        VALE_CALC = -9.969372904989e+04 },
    _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'AB', NOM_CMP = 'DY', TYPE_TEST = 'MIN',
        REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 5.0e-4, LEGENDE = methode,
        VALE_CALC = -5.000451196223e-02 },
    _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'AB', NOM_CMP = 'DY', TYPE_TEST = 'MAX',
        REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 5.0e-4, LEGENDE = methode,
        VALE_CALC = -4.999457564899e-02 },
  } }
end

-- Node by node on AB: the kept factorisation against the whole-system solve, every node, to 1e-10
-- of the component's largest magnitude on AB (absolute: an open node's LAGS_C is 0; this run's
-- largest differences: LAGS_C 1.5e-13, DY 1.7e-14 of their scales). Every node, in AB's order, so
-- that the checks do not depend on which node the round-off of one run makes the worst.
local function lags(R)
  return POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'AB', RESULTAT = R, NOM_CHAM = 'DEPL',
                                     GROUP_NO = 'AB', NOM_CMP = { 'DY', 'LAGS_C' }, NUME_ORDRE = 1 } }
end
local auto, whole = lags(results.AUTO), lags(results.MUMPS)
for _, cmp in ipairs({ 'LAGS_C', 'DY' }) do
  local scale = 0.0
  for i = 1, #whole['NOEUD'] do scale = math.max(scale, math.abs(whole[cmp][i])) end
  for i = 1, #whole['NOEUD'] do
    TEST_TABLE{ TABLE = auto, NOM_PARA = cmp, FILTRE = _F{ NOM_PARA = 'NOEUD', VALE_K = whole['NOEUD'][i] },
                REFERENCE = 'NON_DEFINI', VALE_REFE = whole[cmp][i], CRITERE = 'ABSOLU', PRECISION = 1.0e-10 * scale,
                LEGENDE = 'AUTO vs MUMPS' }
  end
end
TEST_TABLE{ TABLE = auto, NOM_PARA = 'LAGS_C', TYPE_TEST = 'SOMM', REFERENCE = 'NON_DEFINI', LEGENDE = 'AUTO vs MUMPS',
            VALE_REFE = (function() local s = 0.0; for i = 1, #whole['LAGS_C'] do s = s + whole['LAGS_C'][i] end; return s end)(),
            PRECISION = 1.0e-9, VALE_CALC = -4.900076061366e+06 }
FIN()
