-- Must-fail deck: 1/0 is +inf; a real keyword without bounds (an imposed displacement)
-- refuses it too.
-- EXPECT_ERROR: value_infinite\.lua:9: AFFE_CHAR_MECA: DDL_IMPO\[1\]\.DX: expected a finite real, got inf
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
BC = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'CD', DX = 1 / 0, DY = 0.0 } }
FIN()
