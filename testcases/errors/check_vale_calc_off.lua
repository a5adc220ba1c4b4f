-- Must-fail deck: a VALE_CALC off by 1e-5 (relative) is a NOOK check under the default TOLE_MACHINE
-- (1e-6), and the run ends with exit 1. RIGHT's DX in the scene of lib/reaction_scene.lua, recorded
-- from a run (4.285714285714e-03: OK), then that value times 1 + 1e-5 (NOOK).
-- EXPECT_ERROR: ^ OK  NON_REGRESSION DEPL  MAX\(RIGHT\)  DX  refe=4\.285714286e-03  calc=4\.285714286e-03  err=[0-9.e+-]+  tol=1\.000e-06  RELATIF$
-- EXPECT_ERROR: ^NOOK NON_REGRESSION DEPL  MAX\(RIGHT\)  DX  refe=4\.285757143e-03  calc=4\.285714286e-03  err=1\.000e-05  tol=1\.000e-06  RELATIF$
-- EXPECT_ERROR: ^lunaster: 1 check\(s\) OK, 1 NOOK$
-- EXPECT_STATUS: 1
require('lib.reaction_scene')
local function dx(calc)
  return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', GROUP_NO = 'RIGHT', TYPE_TEST = 'MAX',
             VALE_CALC = calc }
end
TEST_RESU{ RESU = { dx(4.285714285714e-03), dx(4.285714285714e-03 * (1 + 1.0e-5)) } }
FIN()
