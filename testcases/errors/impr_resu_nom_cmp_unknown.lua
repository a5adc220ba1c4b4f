-- Must-fail deck: IMPR_RESU NOM_CMP names a component none of the fields written has.
-- EXPECT_ERROR: impr_resu_nom_cmp_unknown\.lua:13: IMPR_RESU: RESU\[1\]\.NOM_CMP: expected components of the fields written \(DX, DY\), got 'SIYY'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                               _F{ GROUP_NO = { 'GH', 'AB' }, DX = 0.0, DY = 0.0 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.5, NOMBRE = 3 } }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, EXCIT = _F{ CHARGE = CHA1 }, INCREMENT = _F{ LIST_INST = L, NUME_INST_FIN = 1 } }
IMPR_RESU{ FORMAT = 'RESULTAT', RESU = _F{ RESULTAT = RESU, NOM_CHAM = 'DEPL', NOM_CMP = { 'DY', 'SIYY' } } }
FIN()
