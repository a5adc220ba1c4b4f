-- Must-fail deck: MATRICE = 'ELASTIQUE' with contact. code_aster keeps the contact terms in
-- the matrix whatever MATRICE says, and with an elastic material that matrix is the tangent:
-- the value would change nothing, so it is refused rather than ignored (without the contact
-- terms the multiplier equations would be empty).
-- EXPECT_ERROR: elastic_matrix_with_contact\.lua:17: STAT_NON_LINE: NEWTON\.MATRICE: expected 'TANGENTE' with contact \(the contact terms belong in the matrix; without contact 'ELASTIQUE' factorises the elastic matrix once for the whole run\), got 'ELASTIQUE'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF' } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA1 },
                      INCREMENT = _F{ LIST_INST = L }, NEWTON = _F{ MATRICE = 'ELASTIQUE' } }
FIN()
