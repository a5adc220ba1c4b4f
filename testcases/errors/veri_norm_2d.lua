-- Must-fail deck: a pressure on boundary cells whose normal points into the body (AFFE_CHAR_MECA
-- VERI_NORM = 'OUI', the default, as code_aster's). The distorted TRIA6 block is meshed clockwise
-- (meshes/patch_tria6_cw.med, tools/make_meshes.sh): LIRE_MAILLAGE reorients its cells, and its
-- SEG3 edges, which keep their order, point inward until MODI_MAILLAGE ORIE_PEAU_2D turns them
-- (testcases/clockwise_2d_pressure.lua does). The positive pressure would pull on TOP instead of
-- pushing: refused, naming the group, how many of its cells point inward, and the fix.
-- EXPECT_ERROR: veri_norm_2d\.lua:16: AFFE_CHAR_MECA: PRES_REP\[1\]\.GROUP_MA: expected boundary cells whose normal points out of the body they bound \(VERI_NORM = 'OUI'\), got group 'TOP': 3 of 3 cells point into their body \(M8, M10, M12\)$
-- EXPECT_ERROR: ORIE_PEAU_2D = _F\{ GROUP_MA = 'TOP' \}
-- EXPECT_ERROR: VERI_NORM = 'NON' applies the pressure on the cells as they are
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_tria6_cw.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DX = 0.0, DY = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'TOP', PRES = 1.0e4 } }
FIN()
