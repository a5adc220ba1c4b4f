-- SOLVEUR options by code_aster's names, each changing how the system is factorised, not the
-- answer: METHODE='MUMPS' with each RENUM (AUTO, METIS, AMD, AMF, QAMD, PORD) and each
-- GESTION_MEMOIRE (IN_CORE, OUT_OF_CORE: the factors on disk, in $TMPDIR else /tmp; AUTO), and
-- PCENT_PIVOT = 50 (MUMPS's working space: the analysis's estimate + 50 %, which the log states),
-- PRETRAITEMENTS = 'SANS' (no scaling nor permutation before the analysis; NPREC = -1, as the
-- unscaled pivots of the contact multipliers would fail the null-pivot test) and POSTTRAITEMENTS =
-- 'FORCE' (iterative refinement until a step gains nothing), TYPE_RESOL = 'NONSYM' (an LU of the
-- symmetric systems) and 'SYMGEN' (LDL^T with pivoting, also of the SPD one), ACCELERATION = 'LR'
-- with LOW_RANK_SEUIL = 1e-9 (block low-rank factors; the log says how many entries they kept)
-- and 'LR+' with -1e-9 (the UCFS variant; LR+'s consortium settings fall back to LR, as the log
-- says), MIXER_PRECISION = 'OUI' (single-precision factors, each solve refined in double precision),
-- FILTRAGE_MATRICE = 1e-3 on the glued scene (MUMPS factorises the matrix without its entries
-- |a_ij| <= 1e-3 (|a_ii| + |a_jj|), the log counts them, and refinement makes up for them);
-- METHODE='MULT_FRONT' with RENUM METIS, MD, MDA; METHODE='LDLT' with RENUM RCMK (reverse
-- Cuthill-McKee) and SANS (no reordering). The log names the ordering used and says when the
-- factors are out of core.
-- 1. SSNP121 I's geometry glued (meshes/glued3d_hexa20.med: two unit cubes stacked), ENCAST
--    clamped, SURCHA moved by DZ = -0.1, E = 2e6, NU = 0, through STAT_NON_LINE and
--    MECA_NON_LINE: DZ = -0.05 m on the interface and SIZZ = -1e5 Pa everywhere, to 1e-8. A
--    symmetric positive definite system: CHOLMOD for MULT_FRONT and LDLT.
-- 2. SSNP121 A (ssnp121a.lua: CONTINUE, SIMPSON ORDRE_INT=4, CONTACT_INIT='NON'), for the
--    MULT_FRONT, LDLT and GESTION_MEMOIRE settings: a symmetric indefinite system of about 640
--    unknowns (contact multipliers: UMFPACK for MULT_FRONT and LDLT, which takes the same
--    orderings). LAGS_C and DY at A, O and B against ssnp121a.lua's own values (VALE_CALC,
--    relative 1e-6) and against the analytical ones at code_aster's 1 %.
-- Under `verify --np 2` the MUMPS models are shared among the ranks and METIS orders the pattern
-- they send to rank 0 (tests/mpi/matr_distribuee.lua checks the log). The orders each backend reports
-- and the fill of each ordering are checked by the unit tests Solvers.MumpsTakesTheOrdering*,
-- Solvers.CholmodAndUmfpackTakeTheOrderingAskedFor, Solvers.ReverseCuthillMckee* and
-- Solvers.MumpsOutOfCoreAgreesWithInCore; PCENT_PIVOT's allocation by
-- Solvers.MumpsWorkspaceRelaxationIsAllocatedAndSaid; what PRETRAITEMENTS changes by
-- Singularity.MumpsWithoutPreprocessingTestsPivotsAsAssembled, TYPE_RESOL's factorisations by
-- Solvers.MumpsFactorisesAsAskedWhereTheSystemAllowsIt, POSTTRAITEMENTS's steps by
-- tests/decks/mumps_posttraitements.lua, the low-rank compression by
-- Solvers.MumpsBlockLowRankCompressesTheFactorsAndRefinementRestoresTheSolve, the single precision
-- by Solvers.MumpsInSinglePrecisionIsRefinedToTheDoublePrecisionSolution, the filtering by
-- Solvers.MumpsFiltersTheMatrixAsCodeAsterDoesAndRefinementRestoresTheSolve, and the log lines of
-- ACCELERATION, MIXER_PRECISION and FILTRAGE_MATRICE by CTest's log.solveur_acceleration.
-- Reference: analytical.
-- Runtime label: fast, 3D, contact, solver.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
local renums = {}
for _, renum in ipairs({ 'AUTO', 'METIS', 'AMD', 'AMF', 'QAMD', 'PORD' }) do
  renums[#renums + 1] = { METHODE = 'MUMPS', RENUM = renum }
end
local others = {
  { METHODE = 'MUMPS', GESTION_MEMOIRE = 'IN_CORE' }, { METHODE = 'MUMPS', GESTION_MEMOIRE = 'OUT_OF_CORE' },
  { METHODE = 'MUMPS', GESTION_MEMOIRE = 'AUTO' }, { METHODE = 'MUMPS', PCENT_PIVOT = 50 },
  { METHODE = 'MUMPS', PRETRAITEMENTS = 'SANS', NPREC = -1 }, { METHODE = 'MUMPS', POSTTRAITEMENTS = 'FORCE' },
  { METHODE = 'MUMPS', TYPE_RESOL = 'NONSYM' }, { METHODE = 'MUMPS', TYPE_RESOL = 'SYMGEN' },
  { METHODE = 'MUMPS', ACCELERATION = 'LR', LOW_RANK_SEUIL = 1.0e-9 },
  { METHODE = 'MUMPS', ACCELERATION = 'LR+', LOW_RANK_SEUIL = -1.0e-9 }, { METHODE = 'MUMPS', MIXER_PRECISION = 'OUI' },
  { METHODE = 'MULT_FRONT', RENUM = 'METIS' }, { METHODE = 'MULT_FRONT', RENUM = 'MD' },
  { METHODE = 'MULT_FRONT', RENUM = 'MDA' }, { METHODE = 'LDLT', RENUM = 'RCMK' }, { METHODE = 'LDLT', RENUM = 'SANS' },
}
-- FILTRAGE_MATRICE on the glued scene only: SSNP121 A's contact couplings are below 1e-9 of the
-- stiffness's diagonal (testcases/errors/mumps_filtrage_matrice_contact.lua).
local glued_only = { { METHODE = 'MUMPS', FILTRAGE_MATRICE = 1.0e-3 } }
local function label(s)
  return s.METHODE .. (s.RENUM and ' RENUM=' .. s.RENUM or '') ..
         (s.GESTION_MEMOIRE and ' GESTION_MEMOIRE=' .. s.GESTION_MEMOIRE or '') ..
         (s.PCENT_PIVOT and ' PCENT_PIVOT=' .. s.PCENT_PIVOT or '') ..
         (s.PRETRAITEMENTS and ' PRETRAITEMENTS=' .. s.PRETRAITEMENTS or '') ..
         (s.NPREC and ' NPREC=' .. s.NPREC or '') ..
         (s.POSTTRAITEMENTS and ' POSTTRAITEMENTS=' .. s.POSTTRAITEMENTS or '') ..
         (s.TYPE_RESOL and ' TYPE_RESOL=' .. s.TYPE_RESOL or '') ..
         (s.ACCELERATION and ' ACCELERATION=' .. s.ACCELERATION or '') ..
         (s.LOW_RANK_SEUIL and ' LOW_RANK_SEUIL=' .. s.LOW_RANK_SEUIL or '') ..
         (s.MIXER_PRECISION and ' MIXER_PRECISION=' .. s.MIXER_PRECISION or '') ..
         (s.FILTRAGE_MATRICE and ' FILTRAGE_MATRICE=' .. s.FILTRAGE_MATRICE or '')
end

MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/glued3d_hexa20.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                               _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
for _, command in ipairs({ 'STAT_NON_LINE', 'MECA_NON_LINE' }) do
  for _, list in ipairs({ renums, others, glued_only }) do
    for _, s in ipairs(list) do
      local solve = command == 'STAT_NON_LINE' and STAT_NON_LINE or MECA_NON_LINE
      local R = solve{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                       SOLVEUR = _F(s), INCREMENT = _F{ LIST_INST = L_INST } }
      R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' } }
      local legende = 'glued 3D ' .. command .. ' ' .. label(s)
      local function t(cham, cmp, kind, refe, group)
        return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = group,
                   REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-8, LEGENDE = legende }
      end
      TEST_RESU{ RESU = {
        t('SIGM_NOEU', 'SIZZ', 'MIN', -1.0e5), t('SIGM_NOEU', 'SIZZ', 'MAX', -1.0e5),
        t('DEPL', 'DZ', 'MIN', -0.05, 'SURESC'), t('DEPL', 'DZ', 'MAX', -0.05, 'SURESC'),
      } }
    end
  end
end

MA2 = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO2 = AFFE_MODELE{ MAILLAGE = MA2, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CM2 = AFFE_MATERIAU{ MAILLAGE = MA2, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CH2 = AFFE_CHAR_MECA{ MODELE = MO2, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MO2, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                     REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON',
                                ORDRE_INT = 4, COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
-- VALE_CALC: ssnp121a.lua's values (the default solver), from a real run.
local calc = {
  A = { DY = -4.999669690478e-02, LAGS_C = -1.000795227287e+05 },
  O = { DY = -4.997830886910e-02, LAGS_C = -1.003593668221e+05 },
  B = { DY = -4.999669690478e-02, LAGS_C = -1.000795227287e+05 },
}
for _, s in ipairs(others) do
  local R = STAT_NON_LINE{ MODELE = MO2, CHAM_MATER = CM2, CONTACT = CONT, EXCIT = _F{ CHARGE = CH2, FONC_MULT = RAMPE },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                           SOLVEUR = _F(s), CONVERGENCE = _F{ RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 } }
  local checks = {}
  for _, point in ipairs({ 'A', 'O', 'B' }) do
    for _, cmp in ipairs({ 'DY', 'LAGS_C' }) do
      checks[#checks + 1] = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = point, NOM_CMP = cmp,
                                VALE_CALC = calc[point][cmp], REFERENCE = 'ANALYTIQUE',
                                VALE_REFE = cmp == 'DY' and -0.05 or -1.0e5, PRECISION = 1.0e-2,
                                LEGENDE = 'SSNP121 A ' .. label(s) }
    end
  end
  TEST_RESU{ RESU = checks }
end
FIN()
