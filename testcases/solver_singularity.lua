-- STAT_NON_LINE SOLVEUR NPREC and STOP_SINGULIER: when a factorisation calls its matrix
-- singular, and going on past it.
-- Purpose: (1) NPREC. The SSNP121 glued blocks (glued2d_quad4.med): the lower block PLAQUE2
--          (E = 2e6) hangs from the upper one PLAQUE1, whose material is 1e9 times softer and
--          whose top CD is moved by DY = -0.1; nothing else holds PLAQUE2. Its last pivot loses
--          about 9.3 significant digits: with code_aster's default NPREC = 8 the run stops
--          (testcases/errors/singular_soft_link_nprec.lua); with NPREC = 12 it runs (CHOLMOD,
--          METHODE='AUTO') and the whole assembly translates by -0.1. The system's condition
--          number (about 1e9) leaves that translation exact to about 1e-6 only (2.2e-7 in the run
--          this deck was written from, 2.2e-6 with MUMPS; a tighter RESI_GLOB_RELA, 1e-12, is out
--          of the solvers' reach): the tolerance is 1e-5. This is what NPREC = 8 warns of. MUMPS
--          is left out here: on two MPI ranks its other pivot order moves these values by 1e-6,
--          where the suite compares the ranks' values to 1e-8 (the unit tests Singularity.*
--          check its null pivots against NPREC).
--          (2) STOP_SINGULIER='NON'. A QUAD4 patch (patch_quad4.med, 1 x 1, E = 2e6, NU = 0.3,
--          D_PLAN) held in DY only (BOTTOM DY = 0, TOP DY = -0.01): nothing holds it along DX, a
--          rigid translation that the load leaves alone. The run goes on with warnings naming
--          the body and the pivot; the factorisation picks one position along DX (CHOLMOD keeps
--          its pivot of round-off size, or, when round-off makes it negative, as a sanitizer build
--          does, hands the system to MUMPS; MUMPS, which then factorises the SPD system as
--          symmetric indefinite to detect its null pivot, sets it aside: zero DX there) and the
--          stress is the uniaxial one, whatever that position: SIYY = E eps / (1 - NU^2) with
--          eps = -0.01, SIXX = 0.
--          (3) NPREC and a stiff penalty. SSNP121 C's scene (discrete PENALISATION, slave EF,
--          master AB) with E_N = 1e14, 5e7 times E: a pivot loses 8.1 digits, so code_aster's
--          default NPREC = 8 stops the run (testcases/errors/penalty_too_stiff_nprec.lua); with
--          NPREC = 10 it runs, and a penalty that stiff is the Lagrange multipliers' answer: DY at
--          O and A equal those of SSNP121 B (DISCRETE CONTRAINTE on the same scene, the values
--          ssnp121b.lua records, checked as this deck's VALE_CALC; code_aster's SSNP121 B gives
--          -0.050173 at O) to 1e-6 (the run this deck was written from: 1e-9 at O, 1e-8 at A).
-- Reference: analytical (for (3), also lunaster's SSNP121 B values as VALE_CALC). Units SI.
--            Runtime label: fast, contact, solver.
DEBUT()
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

-- (1) A part 1e9 times softer than the one it holds: NPREC = 12 lets the factorisation through.
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/glued2d_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
STIFF = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
SOFT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e-3, NU = 0.3 } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'PLAQUE1', MATER = SOFT },
                                            _F{ GROUP_MA = 'PLAQUE2', MATER = STIFF } } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 } }
R1 = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, SOLVEUR = _F{ NPREC = 12 },
                    COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
TEST_RESU{ RESU = {
  _F{ RESULTAT = R1, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'GH', NOM_CMP = 'DY', TYPE_TEST = 'MIN',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1, PRECISION = 1.0e-5, LEGENDE = 'NPREC=12' },
  _F{ RESULTAT = R1, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'GH', NOM_CMP = 'DY', TYPE_TEST = 'MAX',
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.1, PRECISION = 1.0e-5, LEGENDE = 'NPREC=12' },
} }

-- (2) A free direction that the load leaves alone: STOP_SINGULIER='NON' goes on past it.
MP = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/patch_quad4.med' }
MOP = AFFE_MODELE{ MAILLAGE = MP, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CMP = AFFE_MATERIAU{ MAILLAGE = MP, AFFE = _F{ TOUT = 'OUI', MATER = STIFF } }
BC = AFFE_CHAR_MECA{ MODELE = MOP, DDL_IMPO = { _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                                _F{ GROUP_NO = 'TOP', DY = -0.01 } } }
local syy = 2.0e6 * -0.01 / (1.0 - 0.3 * 0.3)
for _, methode in ipairs({ 'AUTO', 'MUMPS' }) do
  local R = STAT_NON_LINE{ MODELE = MOP, CHAM_MATER = CMP, EXCIT = _F{ CHARGE = BC },
                           SOLVEUR = _F{ METHODE = methode, STOP_SINGULIER = 'NON' },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' } }
  local function t(cmp, kind, refe, extra)
    local f = { RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', NOM_CMP = cmp, TYPE_TEST = kind,
                REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10,
                LEGENDE = 'STOP_SINGULIER=NON ' .. methode }
    for k, v in pairs(extra or {}) do f[k] = v end
    return _F(f)
  end
  TEST_RESU{ RESU = {
    t('SIYY', 'MIN', syy), t('SIYY', 'MAX', syy),
    -- zero to round-off beside |SIYY| (no VALE_CALC around zero)
    t('SIXX', 'MIN', 0.0, { CRITERE = 'ABSOLU', PRECISION = 1.0e-10 * math.abs(syy) }),
    t('SIXX', 'MAX', 0.0, { CRITERE = 'ABSOLU', PRECISION = 1.0e-10 * math.abs(syy) }),
  } }
end

-- (3) A penalty 5e7 times stiffer than the material: NPREC = 10 lets the factorisation through.
MC = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MOC = AFFE_MODELE{ MAILLAGE = MC, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
ELAS = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CMC = AFFE_MATERIAU{ MAILLAGE = MC, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = ELAS } }
CHC = AFFE_CHAR_MECA{ MODELE = MOC, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                 _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT = DEFI_CONTACT{ MODELE = MOC, FORMULATION = 'DISCRETE', REAC_GEOM = 'AUTOMATIQUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'EF', GROUP_MA_MAIT = 'AB', ALGO_CONT = 'PENALISATION', E_N = 1.0e14 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
R3 = STAT_NON_LINE{ MODELE = MOC, CHAM_MATER = CMC, CONTACT = CONT, EXCIT = _F{ CHARGE = CHC, FONC_MULT = RAMPE },
                    SOLVEUR = _F{ NPREC = 10 }, COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
-- VALE_CALC: lunaster's values of SSNP121 B (ssnp121b.lua, Lagrange multipliers on the same scene), which
-- this run gives to 5.7e-9 at O and 1.4e-8 at A: within TOLE_MACHINE 1e-6, the default. VALE_REFE: the
-- analytical -0.05, at SSNP121 B's tolerances (node-to-segment is not exact on these meshes).
TEST_RESU{ RESU = {
  _F{ RESULTAT = R3, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'O', NOM_CMP = 'DY', VALE_CALC = -5.017342932254e-02,
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.0e-2, LEGENDE = 'E_N=1e14 NPREC=10, calc of SSNP121 B' },
  _F{ RESULTAT = R3, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'A', NOM_CMP = 'DY', VALE_CALC = -4.916689305517e-02,
      REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 1.67e-2, LEGENDE = 'E_N=1e14 NPREC=10, calc of SSNP121 B' },
} }
FIN()
