-- Pressurised ring bonded in a sleeve (plane strain, Lame solution): LIAISON_MAIL on a curved,
-- non-matching interface, QUAD8 cells (arc edges curved) and QUAD4 cells (both arcs polygonal).
-- Purpose: AFFE_CHAR_MECA LIAISON_MAIL (each node of the ring's outer arc RING_OUT follows the sleeve
--          cell that holds it) on the meshes of testcases/ring_sleeve_mortar_quad8.lua (ring 48 x 8
--          QUAD8, sleeve 40 x 8) and testcases/ring_sleeve_mortar.lua (ring 96 x 16 QUAD4, sleeve 80 x
--          16), with the multipliers eliminated (SOLVEUR ELIM_LAGR = 'OUI': an SPD system).
-- Loads: pressure p = 1e8 Pa on r = a (INNER), r = c free, DX = 0 on x = 0, DY = 0 on y = 0; ring E1 =
--          2e11 Pa, nu1 = 0.3; sleeve E2 = 1e11 Pa, nu2 = 0.25.
-- Reference: analytical (Lame), derived in testcases/ring_sleeve_mortar_quad8.lua. The interface stays
--          in compression and carries no shear by symmetry, so the bonded solution is the
--          frictionless contact one: interface pressure q = 1.5660243999877e7 Pa, u_r(b) =
--          4.299575919609e-4 m (P_X, P_Y on the ring, Q_X on the sleeve), u_r(a) = 5.607426016410e-4 m
--          (A_Y), u_r(c) = 3.775237392827e-4 m (C_X); the radial stress at r = b on the x axis,
--          SIXX = -q (P_X, Q_X).
-- What limits it: ties of nodes to cells do not pass the patch test on non-matching meshes (the
--          forces a slave node passes on through the shape functions are not the master face's own),
--          and the sleeve's cells follow the circle only to O(h^3) (QUAD8) or O(h^2) (QUAD4 chords).
-- What we get (measured, PRECISION = the error rounded up, VALE_CALC to 1e-6): QUAD8 displacements
--          within 7.9e-6 of Lame's (mortar contact on this mesh: 3.6e-6), the radial stress at the
--          interface nodes within 2.7e-2 (nodal stresses, extrapolated from each side's cells); QUAD4
--          displacements within 2e-4 (mortar contact: up to 1.4e-2, with slave nodes open), the stress
--          within 6.5e-2.
-- Runtime label: fast.
DEBUT()
local p, q = 1.0e8, 1.5660243999877e+07
local ub, ua, uc = 4.299575919609e-04, 5.607426016410e-04, 3.775237392827e-04
RING = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
SLEEVE = DEFI_MATERIAU{ ELAS = _F{ E = 1.0e11, NU = 0.25 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
-- Per mesh: the checks (group, field, component, reference, PRECISION, VALE_CALC from a real run).
local cases = {
  { file = 'ring_sleeve_mortar_quad8.med', label = 'QUAD8', checks = {
      { 'P_X', 'DEPL', 'DX', ub, 4.5e-6, 4.299557004e-04 },            -- measured 4.40e-6
      { 'P_Y', 'DEPL', 'DY', ub, 4.5e-6, 4.299557004e-04 },            -- measured 4.40e-6
      { 'Q_X', 'DEPL', 'DX', ub, 4.5e-6, 4.299557004e-04 },            -- measured 4.40e-6
      { 'A_Y', 'DEPL', 'DY', ua, 1.6e-6, 5.607434473e-04 },            -- measured 1.51e-6
      { 'C_X', 'DEPL', 'DX', uc, 8.0e-6, 3.775207696e-04 },            -- measured 7.87e-6
      { 'P_X', 'SIGM_NOEU', 'SIXX', -q, 2.7e-2, -1.524272649e+07 },    -- measured 2.67e-2
      { 'Q_X', 'SIGM_NOEU', 'SIXX', -q, 2.2e-2, -1.599619818e+07 } } },  -- measured 2.15e-2
  { file = 'ring_sleeve_mortar.med', label = 'QUAD4', checks = {
      { 'P_X', 'DEPL', 'DX', ub, 1.2e-4, 4.300069873e-04 },            -- measured 1.15e-4
      { 'P_Y', 'DEPL', 'DY', ub, 1.2e-4, 4.300069873e-04 },            -- measured 1.15e-4
      { 'Q_X', 'DEPL', 'DX', ub, 1.2e-4, 4.300069873e-04 },            -- measured 1.15e-4
      { 'A_Y', 'DEPL', 'DY', ua, 2.0e-4, 5.606314012e-04 },            -- measured 1.98e-4
      { 'C_X', 'DEPL', 'DX', uc, 1.2e-4, 3.774822537e-04 },            -- measured 1.10e-4
      { 'P_X', 'SIGM_NOEU', 'SIXX', -q, 6.5e-2, -1.666918826e+07 },    -- measured 6.44e-2
      { 'Q_X', 'SIGM_NOEU', 'SIXX', -q, 3.4e-2, -1.513230652e+07 } } },  -- measured 3.37e-2
}
for _, case in ipairs(cases) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = case.file }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'RING', MATER = RING },
                                                    _F{ GROUP_MA = 'SLEEVE', MATER = SLEEVE } } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO,
                             DDL_IMPO = { _F{ GROUP_NO = { 'X0_RING', 'X0_SLEEVE' }, DX = 0.0 },
                                          _F{ GROUP_NO = { 'Y0_RING', 'Y0_SLEEVE' }, DY = 0.0 } },
                             PRES_REP = _F{ GROUP_MA = 'INNER', PRES = p },
                             LIAISON_MAIL = _F{ GROUP_MA_MAIT = 'SLEEVE', GROUP_MA_ESCL = 'RING_OUT' } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                           SOLVEUR = _F{ ELIM_LAGR = 'OUI' } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' } }
  local resu = {}
  for _, c in ipairs(case.checks) do
    resu[#resu + 1] = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = c[2], GROUP_NO = c[1], NOM_CMP = c[3],
                          REFERENCE = 'ANALYTIQUE', VALE_REFE = c[4], PRECISION = c[5], VALE_CALC = c[6],
                          LEGENDE = case.label }
  end
  TEST_RESU{ RESU = resu }
end
FIN()
