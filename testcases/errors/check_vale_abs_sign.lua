-- Must-fail deck: VALE_ABS changes what is compared. The unit square of lib/reaction_scene.lua is
-- pressed by DY = -0.01 on TOP: DY = -0.01 there. Against the reference +0.01, VALE_ABS = 'OUI'
-- compares |DY| with |0.01| (OK); without it (VALE_ABS = 'NON', the default) -0.01 differs from
-- +0.01 by 200 % (NOOK), and the run ends with exit 1.
-- EXPECT_ERROR: ^ OK  ANALYTIQUE     DEPL  MIN\(TOP\)  DY  \(absolute values\)  refe=1\.000000000e-02  calc=1\.000000000e-02  err=[0-9.e+-]+  tol=1\.000e-10  RELATIF$
-- EXPECT_ERROR: ^NOOK ANALYTIQUE     DEPL  MIN\(TOP\)  DY  refe=1\.000000000e-02  calc=-1\.000000000e-02  err=2\.000e\+00  tol=1\.000e-10  RELATIF$
-- EXPECT_ERROR: ^lunaster: 1 check\(s\) OK, 1 NOOK$
-- EXPECT_STATUS: 1
require('lib.reaction_scene')
local function dy(vale_abs)
  return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DY', GROUP_NO = 'TOP', TYPE_TEST = 'MIN',
             VALE_ABS = vale_abs, REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.01, PRECISION = 1.0e-10 }
end
TEST_RESU{ RESU = { dy('OUI'), dy('NON') } }
FIN()
