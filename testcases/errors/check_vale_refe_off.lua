-- Must-fail deck: a VALE_REFE off by twice its PRECISION is a NOOK check, and the run ends with exit 1.
-- The unit square of lib/reaction_scene.lua (D_PLAN, NU = 0.3) pressed by DY = -0.01 on TOP, held by
-- LEFT DX = 0 and BOTTOM DY = 0, widens uniformly: DX = 0.3/0.7 x 0.01 on RIGHT (uniaxial plane
-- strain), to round-off. Checked against that value (OK), then against it times 1 + 2 x 1e-3 at
-- PRECISION 1e-3 (a relative difference of 2e-3/(1 + 2e-3) = 1.996e-3: NOOK).
-- EXPECT_ERROR: ^ OK  ANALYTIQUE     DEPL  MAX\(RIGHT\)  DX  refe=4\.285714286e-03  calc=4\.285714286e-03  err=[0-9.e+-]+  tol=1\.000e-03  RELATIF$
-- EXPECT_ERROR: ^NOOK ANALYTIQUE     DEPL  MAX\(RIGHT\)  DX  refe=4\.294285714e-03  calc=4\.285714286e-03  err=1\.996e-03  tol=1\.000e-03  RELATIF$
-- EXPECT_ERROR: ^lunaster: 1 check\(s\) OK, 1 NOOK$
-- EXPECT_STATUS: 1
require('lib.reaction_scene')
local DX, PRECISION = 0.3 / 0.7 * 0.01, 1.0e-3
local function dx(refe)
  return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', GROUP_NO = 'RIGHT', TYPE_TEST = 'MAX',
             REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = PRECISION }
end
TEST_RESU{ RESU = { dx(DX), dx(DX * (1 + 2 * PRECISION)) } }
FIN()
