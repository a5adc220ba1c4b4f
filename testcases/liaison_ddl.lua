-- Linear relations between displacement components (AFFE_CHAR_MECA LIAISON_DDL, LIAISON_UNIF) on a distorted
-- 3x3 QUAD4 block [0,1]^2 (patch_quad4.med; top nodes N14 (0,1) N13 (1/3,1) N15 (2/3,1) N16 (1,1)
-- = C11), plane strain, E = 1e6 Pa, NU = 0.3.
-- Purpose: the three uses of the relation facility, each of which the exact field needs:
--   - a rigid loading plate: the DY of N13, N14, N15 tied to that of C11 (two terms, COEF_IMPO 0,
--     a Lagrange multiplier each);
--   - an imposed displacement written as a relation of one term, 2 DY(C11) = 0.2 (it becomes a
--     Dirichlet condition, DY(C11) = 0.1, no multiplier);
--   - the rigid sliding fixed by a two-term relation with a right-hand side, DX(C00) + DX(C10) =
--     0.1, which FONC_MULT scales as it scales DDL_IMPO.
--   BOTTOM: DY = 0. Loads ramp linearly in time, instants 0.5 and 1.
--   A second run (R2) writes the plate as LIAISON_UNIF (GROUP_MA = 'TOP', DDL = 'DY': one
--   unknown DY on the four top nodes; SOLVEUR ELIM_LAGR = 'NON', the default: a multiplier
--   each) and gives the same state; a third (R3, code_aster 17's MECA_NON_LINE) solves R2's
--   relations for one unknown each (ELIM_LAGR = 'OUI': no multipliers, an SPD system that
--   CHOLMOD factorises) and gives it too.
-- Reference: analytical (Hooke's law, plane strain, SIXX = 0): EPYY = 0.1 t, SIYY = E EPYY /
--            (1 - NU^2), EPXX = -NU / (1 - NU) EPYY; the relation on DX gives DX(C00) =
--            (0.1 t - EPXX) / 2 and DX(C10) = DX(C00) + EPXX. The isoparametric QUAD4 reproduces
--            the linear field on the distorted block to round-off: every check at 1e-10
--            (SIXX absolute, 1e-6 Pa against SIYY = 1.1e5 Pa). Units SI.
-- What we get: every value within 6e-15 (relative) of the analytical one, SIXX within 3.1e-10 Pa.
-- Runtime label: fast.
DEBUT()
local E, NU = 1.0e6, 0.3
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO,
                     DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                     LIAISON_DDL = { _F{ NOEUD = { 'N13', 'N16' }, DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 }, COEF_IMPO = 0.0 },
                                     _F{ NOEUD = { 'N14', 'N16' }, DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 }, COEF_IMPO = 0.0 },
                                     _F{ NOEUD = { 'N15', 'N16' }, DDL = { 'DY', 'DY' }, COEF_MULT = { 1.0, -1.0 }, COEF_IMPO = 0.0 },
                                     _F{ GROUP_NO = 'C11', DDL = 'DY', COEF_MULT = 2.0, COEF_IMPO = 0.2 },
                                     _F{ GROUP_NO = { 'C00', 'C10' }, DDL = { 'DX', 'DX' }, COEF_MULT = { 1.0, 1.0 },
                                         COEF_IMPO = 0.1 } } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, PAS = 0.5 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
CH2 = AFFE_CHAR_MECA{ MODELE = MO,
                      DDL_IMPO = _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                      LIAISON_UNIF = _F{ GROUP_MA = 'TOP', DDL = 'DY' },
                      LIAISON_DDL = { _F{ GROUP_NO = 'C11', DDL = 'DY', COEF_MULT = 2.0, COEF_IMPO = 0.2 },
                                      _F{ GROUP_NO = { 'C00', 'C10' }, DDL = { 'DX', 'DX' }, COEF_MULT = { 1.0, 1.0 },
                                          COEF_IMPO = 0.1 } } }
R2 = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH2, FONC_MULT = RAMPE },
                    COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L },
                    SOLVEUR = _F{ ELIM_LAGR = 'NON' } }
R2 = CALC_CHAMP{ reuse = R2, RESULTAT = R2, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
R3 = MECA_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH2, FONC_MULT = RAMPE },
                    COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L },
                    SOLVEUR = _F{ ELIM_LAGR = 'OUI' } }
R3 = CALC_CHAMP{ reuse = R3, RESULTAT = R3, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6), keyed by
-- '[UNIF |ELIM ]instant field component place' (UNIF: the run R2, ELIM: R3).
local calc = {
  ['0.5 DEPL DY C01'] = 5.000000000000e-02,
  ['0.5 DEPL DY C11'] = 5.000000000000e-02,
  ['0.5 DEPL DY MIN(TOP)'] = 5.000000000000e-02,
  ['0.5 DEPL DY MAX(TOP)'] = 5.000000000000e-02,
  ['0.5 DEPL DX C00'] = 3.571428571429e-02,
  ['0.5 DEPL DX C01'] = 3.571428571429e-02,
  ['0.5 DEPL DX C10'] = 1.428571428571e-02,
  ['0.5 DEPL DX C11'] = 1.428571428571e-02,
  ['0.5 SIGM_NOEU SIYY MIN(BLOCK)'] = 5.494505494505e+04,
  ['0.5 SIGM_NOEU SIYY MAX(BLOCK)'] = 5.494505494506e+04,
  ['0.5 SIGM_NOEU SIXX MIN(BLOCK)'] = -1.209751185263e-10,
  ['0.5 SIGM_NOEU SIXX MAX(BLOCK)'] = 4.049182995107e-11,
  ['1.0 DEPL DY C01'] = 1.000000000000e-01,
  ['1.0 DEPL DY C11'] = 1.000000000000e-01,
  ['1.0 DEPL DY MIN(TOP)'] = 1.000000000000e-01,
  ['1.0 DEPL DY MAX(TOP)'] = 1.000000000000e-01,
  ['1.0 DEPL DX C00'] = 7.142857142857e-02,
  ['1.0 DEPL DX C01'] = 7.142857142857e-02,
  ['1.0 DEPL DX C10'] = 2.857142857143e-02,
  ['1.0 DEPL DX C11'] = 2.857142857143e-02,
  ['1.0 SIGM_NOEU SIYY MIN(BLOCK)'] = 1.098901098901e+05,
  ['1.0 SIGM_NOEU SIYY MAX(BLOCK)'] = 1.098901098901e+05,
  ['1.0 SIGM_NOEU SIXX MIN(BLOCK)'] = -1.146967035540e-10,
  ['1.0 SIGM_NOEU SIXX MAX(BLOCK)'] = 8.338565009912e-11,
  ['UNIF 0.5 DEPL DY C01'] = 5.000000000000e-02,
  ['UNIF 0.5 DEPL DY C11'] = 5.000000000000e-02,
  ['UNIF 0.5 DEPL DY MIN(TOP)'] = 5.000000000000e-02,
  ['UNIF 0.5 DEPL DY MAX(TOP)'] = 5.000000000000e-02,
  ['UNIF 0.5 DEPL DX C00'] = 3.571428571429e-02,
  ['UNIF 0.5 DEPL DX C01'] = 3.571428571429e-02,
  ['UNIF 0.5 DEPL DX C10'] = 1.428571428571e-02,
  ['UNIF 0.5 DEPL DX C11'] = 1.428571428571e-02,
  ['UNIF 0.5 SIGM_NOEU SIYY MIN(BLOCK)'] = 5.494505494505e+04,
  ['UNIF 0.5 SIGM_NOEU SIYY MAX(BLOCK)'] = 5.494505494506e+04,
  ['UNIF 0.5 SIGM_NOEU SIXX MIN(BLOCK)'] = -8.498337421231e-11,
  ['UNIF 0.5 SIGM_NOEU SIXX MAX(BLOCK)'] = 4.619803106345e-11,
  ['UNIF 1.0 DEPL DY C01'] = 1.000000000000e-01,
  ['UNIF 1.0 DEPL DY C11'] = 1.000000000000e-01,
  ['UNIF 1.0 DEPL DY MIN(TOP)'] = 1.000000000000e-01,
  ['UNIF 1.0 DEPL DY MAX(TOP)'] = 1.000000000000e-01,
  ['UNIF 1.0 DEPL DX C00'] = 7.142857142857e-02,
  ['UNIF 1.0 DEPL DX C01'] = 7.142857142857e-02,
  ['UNIF 1.0 DEPL DX C10'] = 2.857142857143e-02,
  ['UNIF 1.0 DEPL DX C11'] = 2.857142857143e-02,
  ['UNIF 1.0 SIGM_NOEU SIYY MIN(BLOCK)'] = 1.098901098901e+05,
  ['UNIF 1.0 SIGM_NOEU SIYY MAX(BLOCK)'] = 1.098901098901e+05,
  ['UNIF 1.0 SIGM_NOEU SIXX MIN(BLOCK)'] = -3.070031569853e-10,
  ['UNIF 1.0 SIGM_NOEU SIXX MAX(BLOCK)'] = 2.030231413027e-10,
  ['ELIM 0.5 DEPL DY C01'] = 5.000000000000e-02,
  ['ELIM 0.5 DEPL DY C11'] = 5.000000000000e-02,
  ['ELIM 0.5 DEPL DY MIN(TOP)'] = 5.000000000000e-02,
  ['ELIM 0.5 DEPL DY MAX(TOP)'] = 5.000000000000e-02,
  ['ELIM 0.5 DEPL DX C00'] = 3.571428571429e-02,
  ['ELIM 0.5 DEPL DX C01'] = 3.571428571429e-02,
  ['ELIM 0.5 DEPL DX C10'] = 1.428571428571e-02,
  ['ELIM 0.5 DEPL DX C11'] = 1.428571428571e-02,
  ['ELIM 0.5 SIGM_NOEU SIYY MIN(BLOCK)'] = 5.494505494505e+04,
  ['ELIM 0.5 SIGM_NOEU SIYY MAX(BLOCK)'] = 5.494505494506e+04,
  ['ELIM 0.5 SIGM_NOEU SIXX MIN(BLOCK)'] = -9.310419107238e-11,
  ['ELIM 0.5 SIGM_NOEU SIXX MAX(BLOCK)'] = 4.900340076343e-11,
  ['ELIM 1.0 DEPL DY C01'] = 1.000000000000e-01,
  ['ELIM 1.0 DEPL DY C11'] = 1.000000000000e-01,
  ['ELIM 1.0 DEPL DY MIN(TOP)'] = 1.000000000000e-01,
  ['ELIM 1.0 DEPL DY MAX(TOP)'] = 1.000000000000e-01,
  ['ELIM 1.0 DEPL DX C00'] = 7.142857142857e-02,
  ['ELIM 1.0 DEPL DX C01'] = 7.142857142857e-02,
  ['ELIM 1.0 DEPL DX C10'] = 2.857142857143e-02,
  ['ELIM 1.0 DEPL DX C11'] = 2.857142857143e-02,
  ['ELIM 1.0 SIGM_NOEU SIYY MIN(BLOCK)'] = 1.098901098901e+05,
  ['ELIM 1.0 SIGM_NOEU SIYY MAX(BLOCK)'] = 1.098901098901e+05,
  ['ELIM 1.0 SIGM_NOEU SIXX MIN(BLOCK)'] = -1.333040605919e-10,
  ['ELIM 1.0 SIGM_NOEU SIXX MAX(BLOCK)'] = 3.393803728340e-11,
}
local checks = {}
local resu, tag = R, ''
local function check(t, field, cmp, refe, place, kind)
  local key = tag .. t .. ' ' .. field .. ' ' .. cmp .. ' ' .. (kind and kind .. '(' .. place .. ')' or place)
  local c = _F{ RESULTAT = resu, INST = t, NOM_CHAM = field, NOM_CMP = cmp, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe,
                VALE_CALC = assert(calc[key], key), PRECISION = 1.0e-10 }
  if refe == 0.0 then c.CRITERE = 'ABSOLU'; c.PRECISION = 1.0e-6; c.ORDRE_GRANDEUR = 1.0e5 end
  if kind then c.TYPE_TEST = kind; c.GROUP_MA = place else c.GROUP_NO = place end
  checks[#checks + 1] = c
end
for run, t in ipairs({ 0.5, 1.0, 0.5, 1.0, 0.5, 1.0 }) do
  if run == 3 then resu, tag = R2, 'UNIF ' end
  if run == 5 then resu, tag = R3, 'ELIM ' end
  local epyy = 0.1 * t
  local epxx = -NU / (1.0 - NU) * epyy
  local dx0 = (0.1 * t - epxx) / 2.0
  for _, corner in ipairs({ 'C01', 'C11' }) do check(t, 'DEPL', 'DY', epyy, corner) end
  check(t, 'DEPL', 'DY', epyy, 'TOP', 'MIN')
  check(t, 'DEPL', 'DY', epyy, 'TOP', 'MAX')
  check(t, 'DEPL', 'DX', dx0, 'C00')
  check(t, 'DEPL', 'DX', dx0, 'C01')
  check(t, 'DEPL', 'DX', dx0 + epxx, 'C10')
  check(t, 'DEPL', 'DX', dx0 + epxx, 'C11')
  check(t, 'SIGM_NOEU', 'SIYY', E * epyy / (1.0 - NU * NU), 'BLOCK', 'MIN')
  check(t, 'SIGM_NOEU', 'SIYY', E * epyy / (1.0 - NU * NU), 'BLOCK', 'MAX')
  check(t, 'SIGM_NOEU', 'SIXX', 0.0, 'BLOCK', 'MIN')
  check(t, 'SIGM_NOEU', 'SIXX', 0.0, 'BLOCK', 'MAX')
end
TEST_RESU{ RESU = checks }
FIN()
