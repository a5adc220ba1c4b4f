-- Must-fail deck: TEST_RESU RESU PARA = 'ITER_GLOB' (code_aster's Newton iterations of a step) is
-- refused by name: a lunaster result does not store them per step.
-- EXPECT_ERROR: test_resu_para_iter_glob\.lua:6: TEST_RESU: RESU\[1\]\.PARA: expected 'INST' \(not stored: a lunaster result keeps fields and instants per NUME_ORDRE, not each step's iterations, residuals or pilot parameters\), got 'ITER_GLOB'$
-- EXPECT_STATUS: 2
require('lib.reaction_scene')
TEST_RESU{ RESU = _F{ RESULTAT = R, NUME_ORDRE = 1, PARA = 'ITER_GLOB', CRITERE = 'ABSOLU',
                      VALE_CALC = 1.0 } }
FIN()
