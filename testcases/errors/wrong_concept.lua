-- Must-fail deck: a concept of the wrong type (a fonction where a list of
-- times is expected). Needs the DEFI_FONCTION handler to create RAMPE.
-- EXPECT_ERROR: wrong_concept\.lua:8: DEFI_LIST_INST: DEFI_LIST\.LIST_INST: expected listr8 concept, got fonction RAMPE
-- EXPECT_STATUS: 2
DEBUT()

RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
TIMES = DEFI_LIST_INST{ DEFI_LIST = _F{ LIST_INST = RAMPE } }
FIN()
