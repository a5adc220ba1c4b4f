-- Must-fail deck: a pressure on 3D boundary faces pointing into the body. The distorted PENTA6 block
-- is meshed mirrored (meshes/patch_penta6_cw.med): LIRE_MAILLAGE reorients its cells, and its faces
-- (TRIA3 on TOP and BOTTOM, QUAD4 on the sides), which keep their order, point inward until
-- MODI_MAILLAGE ORIE_PEAU_3D turns them. RIGHT is oriented first and passes the check
-- (AFFE_CHAR_MECA VERI_NORM = 'OUI', the default); TOP is refused, naming the fix.
-- EXPECT_ERROR: veri_norm_3d\.lua:15: AFFE_CHAR_MECA: PRES_REP\[2\]\.GROUP_MA: expected boundary cells whose normal points out of the body they bound \(VERI_NORM = 'OUI'\), got group 'TOP': 8 of 8 cells point into their body \(M9, M10, M11, \.\.\.\)$
-- EXPECT_ERROR: MA = MODI_MAILLAGE\{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_3D = _F\{ GROUP_MA = 'TOP' \} \}
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_penta6_cw.med' }
MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_3D = _F{ GROUP_MA = 'RIGHT' } }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     PRES_REP = { _F{ GROUP_MA = 'RIGHT', PRES = 1.0e4 },
                                  _F{ GROUP_MA = 'TOP', PRES = 1.0e4 } } }
FIN()
