-- SSNP121 C: the contact patch test with the DISCRETE formulation, ALGO_CONT='PENALISATION' (a spring
--            of stiffness E_N = 1e7 on each penetrating slave node, node-to-segment), REAC_GEOM='AUTOMATIQUE'.
-- Slave EF (11 SEG2, lower block), master AB (12 SEG2, upper block): the roles are swapped with
-- respect to model A, as in code_aster's deck. Seed syntax: AFFE_CHAR_MECA/CONTACT with COMP_ELAS.
-- Reference: analytical SIYY = -1e5 Pa and DY = -0.05 m at A, O, B (nodes of AB). SIYY is the nodal
-- average of SIGM_ELNO (SIGM_NOEU). Node-to-segment fails the patch test on non-matching meshes:
-- code_aster finds SIYY -0.97875e5 at O (2.1 %) and -1.07413e5 at A, B (7.4 %), DY -0.051061 at O
-- (2.1 %) and -0.049651 at A, B (0.7 %). Tolerances are code_aster's. Runtime label: fast, contact.
-- The same contact in the current syntax (DEFI_CONTACT FORMULATION='DISCRETE', ALGO_CONT='PENALISATION',
-- E_N, passed as STAT_NON_LINE CONTACT) must mean the same thing: RESU_DC is checked against the very
-- same VALE_CALC.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CHA2 = AFFE_CHAR_MECA{ MODELE = MO,
                       CONTACT = _F{ METHODE = 'PENALISATION', E_N = 1.0e7, GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB',
                                     REAC_GEOM = 'AUTOMATIQUE' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT,
                      EXCIT = { _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, _F{ CHARGE = CHA2 } },
                      COMP_ELAS = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', REAC_GEOM = 'AUTOMATIQUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB', ALGO_CONT = 'PENALISATION', E_N = 1.0e7 } }
RESU_DC = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                         COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
RESU_DC = CALC_CHAMP{ reuse = RESU_DC, RESULTAT = RESU_DC, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }

-- calc: lunaster's own value from a real run (VALE_CALC, non-regression, relative 1e-6).
for _, r in ipairs({ RESU, RESU_DC }) do
  local function check(point, field, cmp, calc, refe, precision)
    return _F{ RESULTAT = r, NUME_ORDRE = 1, NOM_CHAM = field, GROUP_NO = point, NOM_CMP = cmp, VALE_CALC = calc,
               REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = precision }
  end
  TEST_RESU{ RESU = {
    check('O', 'SIGM_NOEU', 'SIYY', -9.787502141918e+04, -1.0e5, 2.13e-2),
    check('A', 'SIGM_NOEU', 'SIYY', -1.074125611688e+05, -1.0e5, 7.5e-2),
    check('B', 'SIGM_NOEU', 'SIYY', -1.074125611688e+05, -1.0e5, 7.5e-2),
    check('O', 'DEPL', 'DY', -5.106063420055e-02, -0.05, 2.13e-2),
    check('A', 'DEPL', 'DY', -4.965069582285e-02, -0.05, 0.7e-2),
    check('B', 'DEPL', 'DY', -4.965069582285e-02, -0.05, 0.7e-2),
  } }
end
FIN()
