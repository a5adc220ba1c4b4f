-- Must-fail deck: SOLVEUR ELIM_LAGR = 'OUI' (linear relations solved for one unknown each) beside mortar
-- contact with ALGO_CONT = 'LAGRANGIEN', which eliminates the slave nodes' normal displacements
-- itself: the two sets of eliminations are not closed against each other, so the run is refused.
-- EXPECT_ERROR: elim_lagr_with_mortar\.lua:23: STAT_NON_LINE: SOLVEUR\.ELIM_LAGR: expected 'NON' with mortar contact \(ALGO_CONT = 'LAGRANGIEN'\), which eliminates unknowns itself, got 'OUI' and 1 linear relation\(s\)
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DY = -0.1 },
                                    _F{ GROUP_NO = 'D', DX = 0.0 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } },
                       LIAISON_DDL = _F{ GROUP_NO = { 'C', 'D' }, DDL = { 'DX', 'DX' }, COEF_MULT = { 1.0, -1.0 },
                                         COEF_IMPO = 0.0 } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'OUI' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST }, SOLVEUR = _F{ ELIM_LAGR = 'OUI' } }
FIN()
