-- Must-fail deck (seed syntax, which offers INTEGRATION='NOEUD'): a nodal contact rule on an AXIS model gives the slave node on the axis (r = 0,
-- where the measure r dl vanishes) no weight, so its contact pressure would have no equation.
-- EXPECT_ERROR: axis_contact_nodal_rule\.lua:15: STAT_NON_LINE: contact zone AB/EF: INTEGRATION='NOEUD' on an AXIS model gives slave node N[0-9]+, on the axis \(r = 0\), no weight
-- EXPECT_ERROR: use INTEGRATION='GAUSS' \(or 'AUTO', which is Gauss on AXIS models\)
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/axis_contact_nonmatching.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 }, _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = AFFE_CHAR_MECA{ MODELE = MO, CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                                                  MODL_AXIS = 'OUI', INTEGRATION = 'NOEUD', CONTACT_INIT = 'NON' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, EXCIT = { _F{ CHARGE = CHA }, _F{ CHARGE = CONT } },
                      COMP_ELAS = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST } }
FIN()
