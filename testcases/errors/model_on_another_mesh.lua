-- Must-fail deck: AFFE_MATERIAU MODELE must be a model of MAILLAGE (it was accepted unchecked).
-- EXPECT_ERROR: model_on_another_mesh\.lua:9: AFFE_MATERIAU: MODELE: expected a model of mesh 'MB' \(MAILLAGE\), got 'MO', a model of mesh 'MA'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/unit_quad4.med' }
MB = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/unit_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MB, MODELE = MO, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
FIN()
