-- Must-fail deck: SSNP121 D with discrete contact (CONTRAINTE), whose QUAD8 contact faces tie each
-- mid-side node to the mean of its edge's vertices (code_aster's CONTACT_8 relations). DDL_IMPO
-- holds the three nodes of one slave edge in DX, N426 and N427 (the vertices) at 0 and N434 (their
-- mid-side node) at 0.01: no unknown is left to satisfy that tie, and the imposed values contradict
-- it. Such a tie gets no multiplier and used to be dropped without a word (the mid-side node then
-- simply sat off its edge); the message names the tie by its node and component.
-- EXPECT_ERROR: quad8_tie_imposed_contradiction\.lua:21: STAT_NON_LINE: discrete contact's tie of QUAD8 mid-side node N434 \(DX\) relates imposed unknowns only, and their imposed values contradict it at t = 1: its terms sum to 0\.000625, its right-hand side is 0; change one of the imposed values it relates, or remove the relation if the deck wrote it
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 },
                                    _F{ NOEUD = { 'N426', 'N427' }, DX = 0.0 }, _F{ NOEUD = 'N434', DX = 0.01 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE',
                     ZONE = _F{ GROUP_MA_ESCL = 'SURMAI', GROUP_MA_MAIT = 'SURESC', ALGO_CONT = 'CONTRAINTE' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA1 },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
FIN()
