-- Must-fail deck: mortar contact's exact method (DEFI_CONT ALGO_CONT='LAGRANGIEN') on a mesh read in
-- parts (PARTITIONNEUR) is not written yet (docs/distributed-model.md, step 5: it eliminates the slave
-- surface's normal unknowns, which takes the whole stiffness columns of the slave nodes); the other
-- contact methods solve on parts. DEFI_CONT refuses it by name rather than solving it on a whole mesh.
-- EXPECT_ERROR: parts_mortar_lagrangien_refused\.lua:13: DEFI_CONT: ZONE(\[1\])?\.ALGO_CONT: expected 'PENALISATION' with mortar contact on MODELE 'MO', a model on a mesh in parts \(mortar's exact method eliminates unknowns, which is not written for parts yet\), got 'LAGRANGIEN'
-- EXPECT_ERROR: read the mesh without PARTITIONNEUR for this contact method
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med', PARTITIONNEUR = 'PTSCOTCH' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CONT = DEFI_CONT{ MODELE = MO, ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', ALGO_CONT = 'LAGRANGIEN' } }
FIN()
