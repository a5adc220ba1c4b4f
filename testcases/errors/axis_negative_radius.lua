-- Must-fail deck: in an AXIS model x is the radius; the SSNP121 blocks span -1 <= x <= 1, so
-- nodes of AXIS cells lie at r < 0: refused, naming the first such node and its cell.
-- EXPECT_ERROR: axis_negative_radius\.lua:7: AFFE_MODELE: AFFE\[1\]\.MODELISATION: expected 'AXIS' cells with every node at x = r >= 0 \(x is the radius\), got node N1 of cell M93 at x = -1$
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
FIN()
