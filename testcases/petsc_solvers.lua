-- SOLVEUR METHODE='PETSC': every Krylov method and preconditioner on SSNP121 I with mortar contact
-- (ssnp121i_mortar.lua's scene: V1 5x5x1 HEXA8 under V2 4x4x1 HEXA20, non-matching QUAD4/QUAD8
-- interface, DEFI_CONT LAGRANGIEN). The active slave displacements are eliminated, so the system
-- is symmetric positive definite: CG with algebraic multigrid (GAMG, ML, BOOMER) applies, given the
-- rigid-body modes as near null space; FGMRES + LDLT_SP (code_aster's default for PETSC), GMRES + SOR
-- and GMRES + JACOBI as well. The last run is SSNP121 A's saddle-point system (CONTINUE, contact
-- multipliers), which only a factorisation preconditions: FGMRES + LDLT_SP, with INFO=2 printing
-- each Krylov iteration. There REAC_PRECOND = 30 (code_aster's default) keeps the single-precision
-- factorisation for the next contact pass, and when a kept one has not converged after 30
-- iterations the solve factorises its own matrix (CTest log.petsc_reac_precond checks the log);
-- the same scene through MECA_NON_LINE with REAC_PRECOND = 0 (lunaster's default) factorises
-- every matrix. LDLT_SP also runs with its factors in block low rank (LOW_RANK_SEUIL = 1e-8,
-- the log's linear-solve lines name it) and PCENT_PIVOT = 50, through both commands.
-- Reference: analytical, uniform strain -0.05: LAGS_C = -1e5 Pa and DZ = -0.05 m on the interface.
-- RESI_RELA = 1e-12, so the mortar checks hold at 1e-8 as with a direct solver; SSNP121 A's
-- at code_aster's 1 % (the method's own error, as in ssnp121a.lua).
-- Runtime label: fast, contact, 3D, solver.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121i.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
CONT = DEFI_CONT{ MODELE = MO,
                  ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI',
                             ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'INTERPENETRE' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6), per solver.
local calc = {
  CG_GAMG = { -1.0e5, -0.05, -1.0e5, -0.05 },
  CG_ML = { -1.0e5, -0.05, -1.0e5, -0.05 },
  CG_BOOMER = { -1.0e5, -0.05, -1.0e5, -0.05 },
  FGMRES_LDLT_SP = { -1.0e5, -0.05, -1.0e5, -0.05 },
  GMRES_SOR = { -1.0e5, -0.05, -1.0e5, -0.05 },
  GMRES_JACOBI = { -1.0e5, -0.05, -1.0e5, -0.05 },
}
local checks = {}
-- `extra`: more SOLVEUR keywords (LDLT_SP's LOW_RANK_SEUIL and PCENT_PIVOT).
local function run(algorithm, precond, command, extra)
  local solveur = { METHODE = 'PETSC', ALGORITHME = algorithm, PRE_COND = precond, RESI_RELA = 1.0e-12,
                    NMAX_ITER = 500 }
  for k, v in pairs(extra or {}) do solveur[k] = v end
  local resu = command{ MODELE = MO, CHAM_MATER = CHMAT,
                        CONTACT = command == MECA_NON_LINE and _F{ DEFINITION = CONT } or CONT,
                        EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE },
                        COMPORTEMENT = _F{ RELATION = 'ELAS' },
                        INCREMENT = _F{ LIST_INST = L_INST },
                        SOLVEUR = _F(solveur) }
  local values = calc[algorithm .. '_' .. precond]
  for k, point in ipairs({ 'A21', 'A24' }) do
    checks[#checks + 1] = _F{ RESULTAT = resu, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'LAGS_C', GROUP_NO = point,
                              VALE_CALC = values[2 * k - 1], REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5,
                              PRECISION = 1.0e-8 }
    checks[#checks + 1] = _F{ RESULTAT = resu, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DZ', GROUP_NO = point,
                              VALE_CALC = values[2 * k], REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05,
                              PRECISION = 1.0e-8 }
  end
end
run('CG', 'GAMG', STAT_NON_LINE)
run('CG', 'ML', STAT_NON_LINE)
run('CG', 'BOOMER', MECA_NON_LINE)
run('FGMRES', 'LDLT_SP', STAT_NON_LINE)
for _, command in ipairs({ STAT_NON_LINE, MECA_NON_LINE }) do
  run('FGMRES', 'LDLT_SP', command, { LOW_RANK_SEUIL = 1.0e-8, PCENT_PIVOT = 50 })
end
run('GMRES', 'SOR', STAT_NON_LINE)
run('GMRES', 'JACOBI', STAT_NON_LINE)
TEST_RESU{ RESU = checks }

-- SSNP121 A (2D, CONTINUE, CONTACT_INIT='NON'): a saddle point once contact is active.
MA2 = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121a.med' }
MO2 = AFFE_MODELE{ MAILLAGE = MA2, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
CHMAT2 = AFFE_MATERIAU{ MAILLAGE = MA2, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
CHA2 = AFFE_CHAR_MECA{ MODELE = MO2, DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                                  _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CONT2 = DEFI_CONTACT{ MODELE = MO2, FORMULATION = 'CONTINUE', ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE',
                      REAC_GEOM = 'CONTROLE', NB_ITER_GEOM = 2,
                      ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
                                 COEF_CONT = 1000.0, CONTACT_INIT = 'NON' } }
RESU2 = STAT_NON_LINE{ MODELE = MO2, CHAM_MATER = CHMAT2, CONTACT = CONT2, INFO = 2,
                       EXCIT = _F{ CHARGE = CHA2, FONC_MULT = RAMPE }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                       INCREMENT = _F{ LIST_INST = L_INST },
                       CONVERGENCE = _F{ RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 },
                       SOLVEUR = _F{ METHODE = 'PETSC', RESI_RELA = 1.0e-12, REAC_PRECOND = 30 } }
RESU3 = MECA_NON_LINE{ MODELE = MO2, CHAM_MATER = CHMAT2, CONTACT = _F{ DEFINITION = CONT2 },
                       EXCIT = _F{ CHARGE = CHA2, FONC_MULT = RAMPE }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                       INCREMENT = _F{ LIST_INST = L_INST },
                       CONVERGENCE = _F{ RESI_GLOB_MAXI = 2e-8, ITER_GLOB_MAXI = 30 },
                       SOLVEUR = _F{ METHODE = 'PETSC', RESI_RELA = 1.0e-12, REAC_PRECOND = 0 } }
for _, r in ipairs({ RESU2, RESU3 }) do
  TEST_RESU{ RESU = {
    _F{ RESULTAT = r, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'LAGS_C', GROUP_NO = 'A',
        VALE_CALC = -1.000795227e+05, REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, PRECISION = 0.01 },
    _F{ RESULTAT = r, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = 'DY', GROUP_NO = 'A',
        VALE_CALC = -4.999669690e-02, REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.05, PRECISION = 0.01 },
  } }
end
FIN()
