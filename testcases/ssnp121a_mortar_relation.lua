-- SSNP121 A with mortar contact and a linear relation on a slave node's normal component: the
-- DY of the slave corner A tied to that of the master corner E, DY(A) - DY(E) = 0 (LIAISON_DDL).
-- Purpose: a relation and a contact condition on the same unknown. Both hold here (the exact
-- state meets the relation), so the relation carries the force at A and A's contact pressure
-- reads 0, while every other slave node keeps the patch test's pressure. The run says so in a
-- warning naming A and its component.
-- Reference: analytical, as ssnp121a_mortar.lua: DY = -0.05 m on AB and EF, SIYY = -1e5 Pa in
--            both blocks, LAGS_C = -1e5 Pa at O and B; at A, LAGS_C = 0 (the relation takes A's
--            share of the contact force: its multiplier, not checked). Units SI.
-- What we get: every value within 1.2e-14 (relative) of the analytical one, LAGS_C(A) exactly 0.
-- Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } },
                       LIAISON_DDL = _F{ GROUP_NO = { 'A', 'E' }, DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 },
                                         COEF_IMPO = 0.0 } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = { 'SIGM_NOEU' } }
local function depl(group, cmp, refe, calc, prec, crit)
  return _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = group, NOM_CMP = cmp,
             REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, VALE_CALC = calc, PRECISION = prec,
             CRITERE = crit or 'RELATIF' }
end
TEST_RESU{ RESU = {
  depl('A', 'LAGS_C', 0.0, 0.0, 1e-9, 'ABSOLU'),
  depl('O', 'LAGS_C', -1.0e5, -1.0e5, 1e-8),
  depl('B', 'LAGS_C', -1.0e5, -1.0e5, 1e-8),
  depl('A', 'DY', -0.05, -0.05, 1e-8),
  depl('E', 'DY', -0.05, -0.05, 1e-8),
  depl('O', 'DY', -0.05, -0.05, 1e-8),
  _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'AB', NOM_CMP = 'SIYY', TYPE_TEST = 'MIN',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, VALE_CALC = -1.0e5, PRECISION = 1e-8 },
  _F{ RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'AB', NOM_CMP = 'SIYY', TYPE_TEST = 'MAX',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, VALE_CALC = -1.0e5, PRECISION = 1e-8 },
} }
FIN()
