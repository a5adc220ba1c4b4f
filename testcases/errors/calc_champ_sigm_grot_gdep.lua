-- Must-fail deck: CALC_CHAMP CONTRAINTE = 'SIGM_ELNO' on a STAT_NON_LINE result under
-- DEFORMATION = 'GROT_GDEP': CALC_CHAMP's stresses from the displacement are small strain's,
-- wrong under large rotations: refused with the reason (SIEF_ELGA holds the Cauchy stresses).
-- EXPECT_ERROR: calc_champ_sigm_grot_gdep\.lua:17: CALC_CHAMP: CONTRAINTE: expected a result in small strains \(DEFORMATION = 'PETIT'\), got 'SIGM_ELNO' on a result with DEFORMATION = 'GROT_GDEP'
-- EXPECT_ERROR: the result's SIEF_ELGA holds the Cauchy stresses
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/unit_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
STEEL = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e5, NU = 0.3 }, ECRO_LINE = _F{ D_SIGM_EPSI = 2000.0, SY = 200.0 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = STEEL } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = 0.01 } } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L },
                   COMPORTEMENT = _F{ RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP', TOUT = 'OUI' } }
CALC_CHAMP{ RESULTAT = R, reuse = R, CONTRAINTE = 'SIGM_ELNO' }
FIN()
