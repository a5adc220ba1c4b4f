-- SSNP121 A stopped at an instant of its list, its fields taken out and printed as code_aster's
-- own SSNP121 decks do: STAT_NON_LINE INCREMENT NUME_INST_FIN, NEWTON REAC_INCR, CONVERGENCE ARRET,
-- CREA_CHAMP OPERATION='EXTR' (tested through TEST_RESU CHAM_NO and CHAM_ELEM, its node by NOEUD or GROUP_NO), IMPR_RESU MODELE,
-- MAILLAGE and NOM_CMP in FORMAT='RESULTAT'.
-- Purpose: the list holds 0, 0.5, 1 and 1.5; NUME_INST_FIN = 2 stops the computation at 1 (index 2,
--          the list's first time being 0), so the result holds NUME_ORDRE 0, 1, 2 (the error deck
--          errors/nume_inst_fin_stops.lua asks for 3). The ramp reaches U0 = -0.1 at t = 1.
-- Reference: analytical, uniform strain in both blocks: DY = U0 t / 2 on AB (-0.025 at t = 0.5,
--            -0.05 at t = 1), SIYY = E U0 t / 2 = -1e5 Pa at t = 1 (the tolerances of code_aster's
--            SSNP121 A, 1 %). Units SI. Runtime label: fast, contact.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', LISSAGE = 'NON',
                     REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON',
                                ORDRE_INT = 4, COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.5, NOMBRE = 3 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.5, 1.5 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      INCREMENT = _F{ LIST_INST = L_INST, NUME_INST_FIN = 2 },
                      NEWTON = _F{ MATRICE = 'TANGENTE', REAC_ITER = 1, REAC_INCR = 1 },
                      CONVERGENCE = _F{ ARRET = 'OUI', RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = 'SIGM_ELNO' }
U_HALF = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_DEPL_R', NOM_CHAM = 'DEPL', RESULTAT = RESU, NUME_ORDRE = 1 }
U_END = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'NOEU_DEPL_R', NOM_CHAM = 'DEPL', RESULTAT = RESU, INST = 1.0 }
SIELNO = CREA_CHAMP{ OPERATION = 'EXTR', TYPE_CHAM = 'ELNO_SIEF_R', NOM_CHAM = 'SIGM_ELNO', RESULTAT = RESU, NUME_ORDRE = 2 }
IMPR_RESU{ MODELE = MO, FORMAT = 'RESULTAT',
           RESU = _F{ MAILLAGE = MA, RESULTAT = RESU, GROUP_NO = 'AB', NOM_CHAM = 'DEPL', NOM_CMP = { 'LAGS_C', 'DY' } } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6).
TEST_RESU{ RESU = { _F{ RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'DEPL', GROUP_NO = 'A', NOM_CMP = 'DY', VALE_CALC = -4.999663108e-02,
                        REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.0e-2 } },
           CHAM_NO = { _F{ CHAM_GD = U_HALF, GROUP_NO = 'A', NOM_CMP = 'DY', LEGENDE = 't = 0.5', VALE_CALC = -2.499822525e-02,
                           REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.025, PRECISION = 1.0e-2 },
                       _F{ CHAM_GD = U_END, GROUP_NO = 'A', NOM_CMP = 'DY', VALE_CALC = -4.999663108e-02,
                           REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.0e-2 },
                       _F{ CHAM_GD = U_END, GROUP_NO = 'O', NOM_CMP = 'LAGS_C', VALE_CALC = -1.003589712e+05,
                           REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 } },
           CHAM_ELEM = { _F{ CHAM_GD = SIELNO, TYPE_TEST = 'MIN', NOM_CMP = 'SIYY', VALE_CALC = -1.003345001e+05,
                             REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 },
                         _F{ CHAM_GD = SIELNO, TYPE_TEST = 'MAX', NOM_CMP = 'SIYY', VALE_CALC = -9.978221297e+04,
                             REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 },
                         _F{ CHAM_GD = SIELNO, MAILLE = 'M93', NOEUD = 'N1', NOM_CMP = 'SIYY', LEGENDE = 'corner A', VALE_CALC = -1.000618857e+05,
                             REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 },
                         -- the same node named by its one-node group
                         _F{ CHAM_GD = SIELNO, MAILLE = 'M93', GROUP_NO = 'A', NOM_CMP = 'SIYY', VALE_CALC = -1.000618857e+05,
                             REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 1.0e-2 } } }
FIN()
