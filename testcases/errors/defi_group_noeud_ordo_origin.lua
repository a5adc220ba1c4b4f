-- Must-fail deck: DEFI_GROUP OPTION = 'NOEUD_ORDO' starts an open line at one of its ends; a node
-- inside the line (the corner (0, 1) of TOP + LEFT) is refused, naming the ends.
-- EXPECT_ERROR: defi_group_noeud_ordo_origin\.lua:8: DEFI_GROUP: CREA_GROUP_NO\[2\]\.GROUP_NO_ORIG: expected an end of the open line \(N1 or N38\), got 'A' \(node N31\)
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad8.med' }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA, CREA_GROUP_MA = _F{ NOM = 'TOP_LEFT', UNION = { 'TOP', 'LEFT' } } }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA, CREA_GROUP_NO = {
  _F{ NOM = 'A', OPTION = 'ENV_SPHERE', POINT = { 0.0, 1.0 }, RAYON = 1.0e-3, PRECISION = 1.0e-3 },
  _F{ NOM = 'LINE', OPTION = 'NOEUD_ORDO', GROUP_MA = 'TOP_LEFT', GROUP_NO_ORIG = 'A' } } }
FIN()
