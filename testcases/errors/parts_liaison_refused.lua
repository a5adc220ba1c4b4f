-- Must-fail deck: linear relations (LIAISON_DDL, LIAISON_UNIF, LIAISON_MAIL) on a mesh read in parts
-- (PARTITIONNEUR) are not written yet (docs/distributed-model.md, step 5): AFFE_CHAR_MECA refuses them
-- on such a model, saying what it takes, rather than solving them on a whole mesh behind the deck's back.
-- EXPECT_ERROR: parts_liaison_refused\.lua:13: AFFE_CHAR_MECA: LIAISON_DDL: expected DDL_IMPO, PRES_REP, FORCE_NODALE or CONTACT on MODELE 'MO', a model on a mesh in parts \(linear relations are not written for parts yet\), got LIAISON_DDL
-- EXPECT_ERROR: read the mesh without PARTITIONNEUR for this deck
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med', PARTITIONNEUR = 'PTSCOTCH' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CHA = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } }
TIE = AFFE_CHAR_MECA{ MODELE = MO, LIAISON_DDL = _F{ GROUP_NO = { 'A', 'B' }, DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 }, COEF_IMPO = 0.0 } }
FIN()
