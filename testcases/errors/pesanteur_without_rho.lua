-- Must-fail deck: PESANTEUR weighs each cell with its material's density; a material without RHO
-- in DEFI_MATERIAU ELAS cannot be weighed (no default density), said where the load meets the
-- materials, in STAT_NON_LINE's EXCIT.
-- EXPECT_ERROR: pesanteur_without_rho\.lua:14: STAT_NON_LINE: EXCIT\[1\]\.CHARGE: expected RHO in DEFI_MATERIAU ELAS for every cell PESANTEUR weighs, got cell M13, whose material \(CHAM_MATER\) has no RHO
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0 },
                     PESANTEUR = _F{ GRAVITE = 9.81, DIRECTION = { 0.0, -1.0, 0.0 } } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                   INCREMENT = _F{ LIST_INST = L } }
FIN()
