-- Must-fail deck: DEFI_GROUP OPTION = 'TUNNEL' is refused by name.
-- EXPECT_ERROR: defi_group_option_tunnel\.lua:6: DEFI_GROUP: CREA_GROUP_NO\[1\]\.OPTION: expected one of 'PLAN', 'ENV_SPHERE', 'ENV_CYLINDRE', 'SEGM_DROI_ORDO', 'NOEUD_ORDO' \(not offered by lunaster\), got 'TUNNEL'
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/patch_quad8.med' }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA, CREA_GROUP_NO = _F{ NOM = 'T', OPTION = 'TUNNEL' } }
FIN()
