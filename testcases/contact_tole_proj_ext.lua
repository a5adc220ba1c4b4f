-- DEFI_CONTACT ZONE TOLE_PROJ_EXT: how far outside a master cell a slave point's projection may
-- fall and still be paired.
-- Purpose: the SSNP121 A blocks (testcases/ssnp121a.med, NU = 0), the upper one pressed by
--          DY = -0.1 and slid by DX = 0.06 on CD: frictionless, it slides whole, and the end B
--          of the slave side AB (x = 1.06 at the end) overhangs the end F of the master side EF
--          (x = 1). EF has 11 cells of 2/11 m, so B's projection lies 0.06 / (1/11) = 0.66
--          reference units outside the last master cell (whose reference segment spans 2).
--          - TOLE_PROJ_EXT = 0.5 (code_aster's default; also 0, and -1: code_aster's negative
--            values forbid any projection outside a cell): B is not paired, no contact there
--            (CONT_NOEU CONT = 0) and B, beyond the lower block, sinks past the master's level.
--          - TOLE_PROJ_EXT = 1: B's projection is brought back onto F, B is paired and pressed
--            there (CONT = 1, a pressure).
--          A (x = -0.94) lies over EF in both: in contact.
-- Reference: CONT at B and A follows from the geometry above (ANALYTIQUE, exact). LAGS_C and DY
--            at B: NON_REGRESSION (recorded from this run; no closed form for the overhang). Not
--            paired, B keeps a LAGS_C of -5.4 Pa against 1e5 Pa under the contact: the value its
--            slave cell's paired Simpson points give it.
--            Units SI. Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.06, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

local cases = {
  { tole = nil, cont_b = 0.0, lags_b = -5.365257317, dy_b = -6.169329853e-02 },  -- the default, 0.5
  { tole = 0.0, cont_b = 0.0, lags_b = -5.365257317, dy_b = -6.169329853e-02 },
  { tole = -1.0, cont_b = 0.0, lags_b = -5.365257317, dy_b = -6.169329853e-02 },
  { tole = 1.0, cont_b = 1.0, lags_b = -5.785478439e+04, dy_b = -5.765733174e-02 },
}
for _, case in ipairs(cases) do
  local zone = { GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', COEF_CONT = 1000.0,
                 CONTACT_INIT = 'NON', TOLE_PROJ_EXT = case.tole }
  CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                       ZONE = _F(zone) }
  RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA1 },
                        COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
  TEST_RESU{ RESU = {
    _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'CONT_NOEU', GROUP_NO = 'B', NOM_CMP = 'CONT',
        REFERENCE = 'ANALYTIQUE', VALE_REFE = case.cont_b, CRITERE = 'ABSOLU', PRECISION = 0.0 },
    _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'CONT_NOEU', GROUP_NO = 'A', NOM_CMP = 'CONT',
        REFERENCE = 'ANALYTIQUE', VALE_REFE = 1.0, CRITERE = 'ABSOLU', PRECISION = 0.0 },
    _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'B', NOM_CMP = 'LAGS_C', VALE_CALC = case.lags_b },
    _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'B', NOM_CMP = 'DY', VALE_CALC = case.dy_b } } }
end
FIN()
