-- Must-fail deck: the thick cylinder of testcases/axis_thick_cylinder.lua (AXIS, a = 1 <= r <= b = 2,
-- QUAD8) meshed mirrored (meshes/axis_cylinder_quad8_cw.med): its inner face LEFT (r = a) points
-- into the wall. Applied as it is, the internal pressure would pull the wall inward (u_r = -9.5333e-4
-- at r = a where Lame gives +9.5333e-4: testcases/veri_norm_axis_cylinder.lua shows both): refused
-- (AFFE_CHAR_MECA VERI_NORM = 'OUI', the default), naming the group and the fix.
-- EXPECT_ERROR: veri_norm_axis\.lua:14: AFFE_CHAR_MECA: PRES_REP\[1\]\.GROUP_MA: expected boundary cells whose normal points out of the body they bound \(VERI_NORM = 'OUI'\), got group 'LEFT': 1 of 1 cells point into their body \(M3\)$
-- EXPECT_ERROR: MA = MODI_MAILLAGE\{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F\{ GROUP_MA = 'LEFT' \} \}
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/axis_cylinder_quad8_cw.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = { 'BOTTOM', 'TOP' }, DY = 0.0 },
                     PRES_REP = _F{ GROUP_MA = 'LEFT', PRES = 1.0e8 } }
FIN()
