-- Must-fail deck: a zero reference under CRITERE='ABSOLU' compares the computed value itself with
-- PRECISION: RIGHT's DX in the scene of lib/reaction_scene.lua (4.29e-3 m, not zero) checked against 0
-- at PRECISION 1e-3 m is NOOK, and the run ends with exit 1; the resultant of LEFT's reactions along
-- x, zero to round-off (nothing pulls along x), passes at PRECISION 1e-6 N (on a load of 2.2e4 N).
-- EXPECT_ERROR: ^ OK  ANALYTIQUE     REAC_NODA  SOMM\(LEFT\)  DX  refe=0\.000000000e\+00  calc=[0-9.e+-]+  err=[0-9.e+-]+  tol=1\.000e-06  ABSOLU$
-- EXPECT_ERROR: ^NOOK ANALYTIQUE     DEPL  MAX\(RIGHT\)  DX  refe=0\.000000000e\+00  calc=4\.285714286e-03  err=4\.286e-03  tol=1\.000e-03  ABSOLU$
-- EXPECT_ERROR: ^lunaster: 1 check\(s\) OK, 1 NOOK$
-- EXPECT_STATUS: 1
require('lib.reaction_scene')
TEST_RESU{ RESU = {
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'REAC_NODA', NOM_CMP = 'DX', GROUP_NO = 'LEFT', TYPE_TEST = 'SOMM',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, CRITERE = 'ABSOLU', PRECISION = 1.0e-6 },
  _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', GROUP_NO = 'RIGHT', TYPE_TEST = 'MAX',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, CRITERE = 'ABSOLU', PRECISION = 1.0e-3 },
} }
FIN()
