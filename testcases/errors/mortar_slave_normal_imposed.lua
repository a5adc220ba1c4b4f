-- Must-fail deck: a mortar slave node under an imposed displacement along the contact normal (here
-- DY = 0 on every node of the slave edge AB, whose normal is -y): the weighted-gap condition and the
-- imposed value cannot both hold. The error names the node and the component and says what to do.
-- EXPECT_ERROR: mortar_slave_normal_imposed\.lua:21: STAT_NON_LINE: slave node N1 of contact zone 1 \(slave 'AB', master 'EF'\) has an imposed displacement DY along the normal to the contact surface
-- EXPECT_ERROR: remove the node from the slave group \(or from the imposed displacement\)
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 },
                                    _F{ GROUP_NO = 'AB', DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      INCREMENT = _F{ LIST_INST = L_INST } }
FIN()
