-- Must-fail deck: mortar slave and master surfaces that do not face each other: AB (bottom of the
-- upper block, normal -y) against GH (bottom of the lower block, normal -y, one metre below). No
-- slave cell overlaps a master cell facing it: the run stops at the first pairing instead of
-- computing without contact.
-- EXPECT_ERROR: mortar_surfaces_not_facing\.lua:21: STAT_NON_LINE: contact zone 1 \(slave 'AB', master 'GH'\): no slave cell overlaps a master cell facing it
-- EXPECT_ERROR: give the slave and master groups as the two sides of one interface
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'GH' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                      INCREMENT = _F{ LIST_INST = L_INST } }
FIN()
