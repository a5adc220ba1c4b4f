-- Automatic step subdivision (DEFI_LIST_INST / ECHEC / ACTION='DECOUPE') rescuing a contact
-- step that does not converge whole.
-- Purpose: the SSNP121 A blocks (testcases/ssnp121a.med, NU = 0) pressed by DY = -0.1 on CD,
--          CONTINUE contact with the geometry updated at every Newton iteration
--          (ALGO_RESO_GEOM='NEWTON'), ITER_GLOB_MAXI = 10. In one step 0 -> 1 Newton does not
--          converge within 10 iterations; split in 4 the last quarter still needs 12 and fails;
--          split once more, every sub-step converges in 8-10 iterations
--          (errors/contact_step_no_subdivision.lua is the same problem without ECHEC: it fails). The sub-steps are stored as steps of
--          their own: NUME_ORDRE 1..7 = INST 0.25, 0.5, 0.75, 0.8125, 0.875, 0.9375, 1.
-- Reference: analytical, uniform strain -0.05 in both blocks: DY = -0.05 m on AB and
--            LAGS_C = E*eps = -1e5 Pa at the end, DY = -0.0375 m at INST 0.75 (linear in the
--            load). Tolerances: 1 % at O (we get 0.3 %); 2 % for DY at the ends A, B (we get
--            1.36 %): the default integration (AUTO) is less accurate at the block ends than
--            SSNP121 A's SIMPSON/ORDRE_INT=4, with which the whole step converges in 3
--            iterations and would not exercise the subdivision. Units SI.
--            Runtime label: fast, contact, nonlinear.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'NEWTON',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
LI = DEFI_LIST_INST{ DEFI_LIST = _F{ LIST_INST = L },
                     ECHEC = _F{ EVENEMENT = 'ERREUR', ACTION = 'DECOUPE', SUBD_PAS = 4, SUBD_NIVEAU = 3 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = LI },
                      CONVERGENCE = _F{ ITER_GLOB_MAXI = 10 } }

local function depl(where, cmp, inst_or_order, refe, precision)
  local check = _F{ RESULTAT = RESU, NOM_CHAM = 'DEPL', GROUP_NO = where, NOM_CMP = cmp,
                    REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = precision }
  if inst_or_order.inst then check.INST = inst_or_order.inst else check.NUME_ORDRE = inst_or_order.order end
  return check
end
local checks = {
  depl('O', 'DY', { inst = 1.0 }, -0.05, 1.0e-2),
  depl('O', 'LAGS_C', { inst = 1.0 }, -1.0e5, 1.0e-2),
  depl('A', 'DY', { inst = 1.0 }, -0.05, 2.0e-2),
  depl('B', 'DY', { inst = 1.0 }, -0.05, 2.0e-2),
  -- the sub-steps are in the result: NUME_ORDRE 3 is INST 0.75, NUME_ORDRE 7 the requested 1.0
  depl('O', 'DY', { order = 3 }, -0.0375, 1.0e-2),
  depl('O', 'DY', { order = 7 }, -0.05, 1.0e-2),
}
TEST_RESU{ RESU = checks }
FIN()
