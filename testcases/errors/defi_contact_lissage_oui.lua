-- Must-fail deck: DEFI_CONTACT LISSAGE = 'OUI' (master normals smoothed at the nodes) is refused
-- rather than run without smoothing.
-- EXPECT_ERROR: defi_contact_lissage_oui\.lua:13: DEFI_CONTACT: LISSAGE: expected 'NON' \(each master cell's own normal\), got 'OUI'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                               _F{ GROUP_NO = { 'GH', 'AB' }, DX = 0.0, DY = 0.0 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.5, NOMBRE = 3 } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', LISSAGE = 'OUI',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF' } }
FIN()
