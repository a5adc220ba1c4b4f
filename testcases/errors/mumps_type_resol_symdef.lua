-- Must-fail deck: SSNP121 A (CONTINUE, CONTACT_INIT = 'NON') with SOLVEUR METHODE = 'MUMPS' and
-- TYPE_RESOL = 'SYMDEF', MUMPS's LDL^T without pivoting. The first pass (no contact yet) is
-- positive definite and goes through; once contact closes, its multipliers make the system
-- symmetric indefinite, which that factorisation cannot take. The run stops as a deck error (not
-- a singular matrix) naming the TYPE_RESOL values that fit.
-- EXPECT_ERROR: mumps_type_resol_symdef\.lua:20: STAT_NON_LINE: MUMPS: a positive definite factorisation \(LDL\^T without pivoting\) was asked for a symmetric indefinite system \(contact or relation multipliers\)
-- EXPECT_ERROR: use SOLVEUR TYPE_RESOL='SYMGEN' or 'NONSYM', or 'AUTO' \(the default: by the system\)
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
                                COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, EXCIT = _F{ CHARGE = CHA1 },
                      COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                      SOLVEUR = _F{ METHODE = 'MUMPS', TYPE_RESOL = 'SYMDEF' } }
FIN()
