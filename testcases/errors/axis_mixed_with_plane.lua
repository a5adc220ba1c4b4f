-- Must-fail deck: AXIS integrates per radian, D_PLAN per unit thickness; one model cannot hold
-- both (their forces would not add up), so a second occurrence of another 2D kind is refused.
-- EXPECT_ERROR: axis_mixed_with_plane\.lua:7: AFFE_MODELE: AFFE\[2\]\.MODELISATION: expected 'AXIS' as in the other occurrences \(an axisymmetric model cannot mix plane modelisations\), got 'D_PLAN'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = { _F{ GROUP_MA = 'BLOCK', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' },
                           _F{ GROUP_MA = 'TOP', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } } }
FIN()
