-- Must-fail deck: DEFI_CONTACT's APPARIEMENT='NODAL' (each slave node with its nearest master
-- node), which lunaster does not do: it pairs by projection on the master surface (MAIT_ESCL).
-- EXPECT_ERROR: contact_appariement_nodal\.lua:9: DEFI_CONTACT: ZONE\[1\]\.APPARIEMENT: expected 'MAIT_ESCL' \(lunaster pairs a slave point with its projection on the master surface
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../friction_patch_2d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
-- A zone otherwise accepted.
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', APPARIEMENT = 'NODAL' } }
FIN()
