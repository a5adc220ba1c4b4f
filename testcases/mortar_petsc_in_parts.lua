-- Mortar contact on a mesh read in parts (LIRE_MAILLAGE PARTITIONNEUR='PTSCOTCH'), solved by PETSc's
-- Krylov methods on the parts: SSNP121 I (ssnp121i_mortar.lua's scene: V1 5x5x1 HEXA8 under V2 4x4x1
-- HEXA20, non-matching QUAD4/QUAD8 interface, DEFI_CONT LAGRANGIEN). Each rank holds its part and the
-- contact surfaces whole (with the cells around the slave nodes, whose unknowns mortar eliminates);
-- the eliminated system is symmetric positive definite, so CG with algebraic multigrid (GAMG, ML,
-- BOOMER, the rigid-body modes as near null space) applies to it in parts, as GMRES + SOR and GMRES +
-- JACOBI do (docs/distributed-model.md, step 5). As petsc_solvers.lua without LDLT_SP, which
-- factorises the whole system on one rank and is refused on a mesh in parts. Runs as one part
-- without mpirun; mpi.contact_parts_suite runs it on 2 and 3 ranks against the whole mesh's values.
-- Reference: analytical, uniform strain -0.05: LAGS_C = -1e5 Pa and DZ = -0.05 m on the interface;
-- RESI_RELA = 1e-12, so every check holds at 1e-8 as with a direct solver.
-- Runtime label: fast, contact, 3D, solver, parts.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121i.med', PARTITIONNEUR = 'PTSCOTCH' }
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
  GMRES_SOR = { -1.0e5, -0.05, -1.0e5, -0.05 },
  GMRES_JACOBI = { -1.0e5, -0.05, -1.0e5, -0.05 },
}
local checks = {}
local function run(algorithm, precond, command)
  local solveur = { METHODE = 'PETSC', ALGORITHME = algorithm, PRE_COND = precond, RESI_RELA = 1.0e-12,
                    NMAX_ITER = 500 }
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
run('GMRES', 'SOR', STAT_NON_LINE)
run('GMRES', 'JACOBI', STAT_NON_LINE)
TEST_RESU{ RESU = checks }

FIN()
