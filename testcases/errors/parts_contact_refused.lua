-- Must-fail deck: contact on a mesh read in parts (PARTITIONNEUR) is not written yet
-- (docs/distributed-model.md, step 5): AFFE_CHAR_MECA refuses CONTACT on such a model, saying what
-- it takes, rather than solving the contact on a whole mesh behind the deck's back.
-- EXPECT_ERROR: parts_contact_refused\.lua:13: AFFE_CHAR_MECA: CONTACT: expected DDL_IMPO, PRES_REP or FORCE_NODALE on MODELE 'MO', a model on a mesh in parts \(linear relations and contact are not written for parts yet\), got CONTACT
-- EXPECT_ERROR: read the mesh without PARTITIONNEUR for this deck
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med', PARTITIONNEUR = 'PTSCOTCH' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CHA = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } }
CONT = AFFE_CHAR_MECA{ MODELE = MO, CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF' } }
FIN()
