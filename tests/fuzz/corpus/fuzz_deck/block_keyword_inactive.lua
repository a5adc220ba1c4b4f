-- Must-fail deck: ORDRE_INT only exists for INTEGRATION = GAUSS, SIMPSON or NCOTES
-- (a conditional block), and its range depends on the scheme. The model is not
-- needed to see these errors: validation reports them all before any handler runs.
-- EXPECT_ERROR: block_keyword_inactive\.lua:10: DEFI_CONTACT: MODELE: expected modele concept \(mandatory keyword\), got nothing
-- EXPECT_ERROR: also ZONE\[1\]\.ORDRE_INT: expected no ORDRE_INT here \(only valid when INTEGRATION = 'GAUSS', 'SIMPSON' or 'NCOTES'\), got ORDRE_INT = 4
-- EXPECT_ERROR: also ZONE\[2\]\.ORDRE_INT: expected integer in \[1, 4\], got 8
-- EXPECT_STATUS: 2
DEBUT()
-- two zones, one error each
CONT = DEFI_CONTACT{ FORMULATION = 'CONTINUE',
                     ZONE = { _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', ORDRE_INT = 4 },
                              _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', ORDRE_INT = 8 } } }
FIN()
