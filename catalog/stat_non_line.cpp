#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

#include <algorithm>

namespace lunaster::catalog {

namespace {

/// SOLVEUR ELIM_LAGR (code_aster's values per METHODE; LAGR2, MUMPS's double-Lagrange option in
/// code_aster, keeps the multipliers here, which are single already).
Keyword elim_lagr(const std::vector<std::string>& names, const std::string& def) {
  std::vector<Scalar> values(names.begin(), names.end());
  return text("ELIM_LAGR",
              "Linear relations (LIAISON_DDL, LIAISON_UNIF, and discrete contact's ties of QUAD8 mid-side nodes): "
              "OUI solves each for one of its unknowns (the free "
              "one of largest coefficient, once the relations before it are substituted) and keeps no "
              "multiplier, so a symmetric positive definite system stays one (CHOLMOD, or CG with algebraic "
              "multigrid); NON gives each relation a Lagrange multiplier (a symmetric indefinite system)" +
                  std::string(def == "LAGR2" ? "; LAGR2 (code_aster's single Lagrange multiplier for MUMPS) is NON "
                                               "here, whose multipliers are single"
                                             : "") +
                  ". The log says which. Not with mortar contact ALGO_CONT='LAGRANGIEN', which eliminates "
                  "unknowns itself")
      .into_values(std::move(values))
      .def(def);
}

Keyword behaviour(const std::string& name, const std::string& doc) {
  return factor(name,
                {text("RELATION", "Constitutive law: linear elasticity, or von Mises plasticity with isotropic "
                                  "hardening, linear (the material's ECRO_LINE) or from a traction curve (its TRACTION)")
                     .into_values({"ELAS", "VMIS_ISOT_LINE", "VMIS_ISOT_TRAC"})
                     .def("ELAS"),
                 text("DEFORMATION", "Strain measure: only PETIT (small strains) is built; the others are refused "
                                     "with the reason")
                     .into_values({"PETIT", "PETIT_REAC", "GROT_GDEP", "SIMO_MIEHE", "GDEF_LOG"})
                     .def("PETIT"),
                 real("RESI_INTE_RELA", "Plane stress (C_PLAN) von Mises laws: the local iteration on the zz strain "
                                        "converges when |sigma_zz| is below this fraction of the stress scale "
                                        "(default: 1e-12, tighter than code_aster's 1e-6); other cases integrate "
                                        "in closed form and do not read it")
                     .range(0.0, std::nullopt),
                 integer("ITER_INTE_MAXI", "Plane stress (C_PLAN) von Mises laws: iterations of that local "
                                           "iteration before the step fails (and is subdivided where DEFI_LIST_INST "
                                           "allows; default 100)")
                     .range(1, std::nullopt),
                 common::tout("Apply to every cell"), common::group_ma("Cell groups with this behaviour")},
                doc)
      .occurs(0, -1)
      .with_rules({at_most_one({"TOUT", "GROUP_MA"})});
}

std::vector<Keyword> keywords(bool meca_non_line) {
  std::vector<Keyword> kws = {
      concept_kw("MODELE", {"modele"}, "Model").required(),
      concept_kw("CHAM_MATER", {"cham_mater"}, "Material field").required(),
      factor("EXCIT",
             {concept_kw("CHARGE", {"char_meca"}, "Load").required(),
              concept_kw("FONC_MULT", {"fonction", "formule"}, "Time multiplier of the load, a function of INST (default: 1 at every time)")},
             "Loads applied")
          .occurs(0, -1),
      meca_non_line ? factor("CONTACT", {concept_kw("DEFINITION", {"char_contact"}, "Contact definition from DEFI_CONT or DEFI_CONTACT").required()},
                             "Contact (code_aster 17 spelling)")
                    : concept_kw("CONTACT", {"char_contact"}, "Contact definition from DEFI_CONTACT or DEFI_CONT"),
      behaviour("COMP_ELAS", "Behaviour (seed syntax; same as COMPORTEMENT)").legacy(),
      behaviour("COMPORTEMENT", "Behaviour (default: linear elasticity everywhere)"),
      factor("INCREMENT",
             {concept_kw("LIST_INST", {"listr8", "list_inst"}, "Time steps").required(),
              real("INST_INIT", "First time computed (default: first of the list)"),
              real("INST_FIN", "Last time computed (default: last of the list)"),
              integer("NUME_INST_FIN",
                      "Last time computed, by its index in LIST_INST (the list's first time is 0): the "
                      "computation stops there, as with INST_FIN at that time")
                  .range(1, std::nullopt)},
             "Time stepping")
          .required()
          .with_rules({at_most_one({"INST_FIN", "NUME_INST_FIN"})}),
      factor("NEWTON",
             {text("MATRICE",
                   "Matrix of Newton's corrections: the tangent, or the elastic matrix factorised once for the whole "
                   "run. With contact, code_aster keeps the contact terms in the matrix: ELASTIQUE is then the elastic "
                   "stiffness plus the contact terms, with linear elasticity the tangent (the log says so)")
                  .into_values({"TANGENTE", "ELASTIQUE"})
                  .def("TANGENTE"),
              integer("REAC_ITER",
                      "Refactorise the tangent every N Newton iterations; 0: only at the first iteration of each "
                      "instant and of each contact pass (always refactorised: its statuses or pairing changed the "
                      "matrix). In between the last factors are reused with the current residual (modified Newton: "
                      "fewer factorisations, more iterations; convergence is judged on the true residual)")
                  .def(1LL)
                  .range(0, std::nullopt),
              integer("REAC_INCR",
                      "Form the matrix anew at the first Newton iteration of every N-th increment (code_aster's "
                      "default 1: every increment, which is what lunaster's driver does; the log says so when "
                      "given). 0 (never at the start of an increment) and N > 1, which keep the previous "
                      "increment's factors, are refused: the driver forms the matrix at each increment's first "
                      "iteration")
                  .range(0, std::nullopt)},
             "Newton's method")
          .by_default(),
      factor("CONVERGENCE",
             {real("RESI_GLOB_RELA", "Largest free residual over the largest load or reaction; 1e-6 unless only RESI_GLOB_MAXI is given").above(0.0),
              real("RESI_GLOB_MAXI", "Largest residual component (N)").above(0.0),
              integer("ITER_GLOB_MAXI", "Maximum Newton iterations per step").def(10LL).range(1, std::nullopt),
              text("ARRET",
                   "OUI: a step whose Newton iterations do not converge (and cannot be split, DEFI_LIST_INST) "
                   "stops the run, its converged steps saved. NON (code_aster goes on with the step's last "
                   "iterate as if converged) is refused: a result that does not satisfy equilibrium would "
                   "pass for one")
                  .into_values({"OUI", "NON"})
                  .def("OUI")},
             "Convergence criteria (both residual criteria must hold when both are given)")
          .by_default(),
      factor("SOLVEUR",
             {text("METHODE",
                   "Linear solver. AUTO, CHOLMOD, LDLT and MULT_FRONT factorise with CHOLMOD (sparse Cholesky) "
                   "when the system is symmetric positive definite. A symmetric indefinite system (contact "
                   "multipliers, mid-side ties; the log says so once) goes, in a run without mpirun, to the "
                   "Schur complement of its multipliers (penalised by 1e-6 of their rows' scale, SPD, "
                   "factorised by CHOLMOD) with GMRES on the true system to a direct solve's accuracy, except "
                   "3D systems of more than 100,000 unknowns; where that gives way (the log says why), under "
                   "mpirun, and for a non-symmetric system, MUMPS factorises it, or UMFPACK below 10,000 "
                   "unknowns in a run without mpirun (no MPI start-up). AUTO also gives 3D "
                   "SPD systems of more than 100,000 unknowns to PETSc's CG with BoomerAMG (relative residual 1e-12; MUMPS "
                   "factorises the system if CG fails, and under mpirun), and "
                   "solves contact (DEFI_CONTACT) with the elastic stiffness factorised once by CHOLMOD, the "
                   "contact surfaces' equations ordered last, when they are at most 2,500 and a twentieth of "
                   "the model, or else only the displacement components the contact terms reach (the normal one "
                   "of a surface square to an axis) with the multipliers, when they are at most 2,500 and their "
                   "dense factorisation costs at most half the elastic one: each contact pass then factorises "
                   "their dense Schur complement only; MUMPS and "
                   "UMFPACK are used as asked; PETSC solves iteratively (a Krylov method and a preconditioner). "
                   "Under mpirun, MUMPS and PETSC share the model among the ranks (Scotch partition, each "
                   "rank assembling its own rows); the other methods give every rank the whole system")
                  .into_values({"AUTO", "MUMPS", "LDLT", "MULT_FRONT", "CHOLMOD", "UMFPACK", "PETSC"})
                  .def("AUTO")},
             "Linear solver")
          .by_default()
          .with_blocks({Block{
              "METHODE",
              {"PETSC"},
              {text("ALGORITHME", "Krylov method: CG (symmetric positive definite systems), GMRES (restarted every 30 "
                                  "iterations, right-preconditioned), FGMRES (flexible GMRES)")
                   .into_values({"FGMRES", "GMRES", "CG"})
                   .def("FGMRES"),
               text("PRE_COND",
                    "Preconditioner: LDLT_SP a single-precision MUMPS factorisation (any system, contact included); "
                    "GAMG (PETSc), ML (Trilinos) and BOOMER (hypre BoomerAMG) algebraic multigrid, given the "
                    "rigid-body modes as near null space (systems without contact multipliers); JACOBI, SOR point "
                    "relaxations; SANS none")
                   .into_values({"LDLT_SP", "GAMG", "ML", "BOOMER", "JACOBI", "SOR", "SANS"})
                   .def("LDLT_SP"),
               real("RESI_RELA", "Relative residual |b - A x| / |b| each linear solve must reach; a solve that does "
                                 "not reach it is a solve failure")
                   .def(1e-6)
                   .above(0.0)
                   .below(1.0),
               integer("NMAX_ITER", "Largest number of Krylov iterations per solve; 0: 100 with PRE_COND = "
                                    "'LDLT_SP' (code_aster's), otherwise no limit but 10,000")
                   .def(0LL)
                   .range(0, std::nullopt)},
              {}},
                        Block{"PRE_COND",
                              {"LDLT_SP"},
                              {integer("REAC_PRECOND",
                                       "The single-precision factorisation serves as preconditioner for the next "
                                       "matrices of the run (Newton iterations, contact passes, instants) while each "
                                       "solve takes at most REAC_PRECOND Krylov iterations; a solve on a kept "
                                       "factorisation that has not converged after REAC_PRECOND iterations factorises "
                                       "its own matrix and solves again (code_aster does so after NMAX_ITER). The "
                                       "log's linear-solve lines say when it was kept. 0 (lunaster's default; "
                                       "code_aster's is 30, and its MECA_NON_LINE always takes 0): every matrix "
                                       "factorised, which on the contact benchmarks "
                                       "was faster (a pass whose statuses changed is not preconditioned by the last "
                                       "one's factors; tests/bench/README.md)")
                                   .def(0LL)
                                   .range(0, std::nullopt),
                               integer("PCENT_PIVOT",
                                       "Working space of the single-precision factorisation beyond MUMPS's estimate, "
                                       "in percent (ICNTL(14)); doubled and the factorisation redone when short "
                                       "(three times at most). code_aster's default 20, MUMPS's own for these systems")
                                   .def(20LL)
                                   .range(1, std::nullopt),
                               real("LOW_RANK_SEUIL",
                                    "Non-zero: the single-precision factors in block low rank (ICNTL(35) = 1), "
                                    "off-diagonal blocks compressed to the singular values above |LOW_RANK_SEUIL| "
                                    "(CNTL(7); negative: the UCFS variant, ICNTL(36) = 1), as code_aster passes it "
                                    "to MUMPS. The preconditioner is coarser: the Krylov iterations make up for "
                                    "it. The linear-solve lines of the log name the threshold. 0: full rank")
                                   .def(0.0)},
                              {}},
                        Block{"METHODE",
                              {"MUMPS"},
                              {text("RENUM",
                                    "MUMPS's fill-reducing ordering: AUTO chooses (AMD on 2D rows, METIS's nested "
                                    "dissection of the mesh's node graph on 3D rows); METIS that nested dissection "
                                    "(under mpirun computed by rank 0 from the pattern the ranks send it, as "
                                    "MUMPS's own analysis does); AMD, AMF, QAMD and PORD MUMPS's own. SCOTCH, "
                                    "PTSCOTCH and PARMETIS are not in Debian's MUMPS build. The log names the "
                                    "ordering used when RENUM is given")
                                   .into_values({"AUTO", "METIS", "AMD", "AMF", "QAMD", "PORD"})
                                   .def("AUTO"),
                               text("GESTION_MEMOIRE",
                                    "Where MUMPS keeps its factors: IN_CORE in memory; OUT_OF_CORE on disk (in "
                                    "$TMPDIR, else /tmp; memory then holds the fronts being factorised, each solve "
                                    "reads the factors back); AUTO in memory unless MUMPS's analysis estimates "
                                    "more than 80 % of the memory available to the process (the machine's, or its memory "
                                    "cgroup's limit, shared among the MPI ranks on the machine, and no more than "
                                    "the run's memory limit leaves: memory_limit, --memory-limit; the log says so). "
                                    "code_aster's EVAL is not offered")
                                   .into_values({"AUTO", "IN_CORE", "OUT_OF_CORE"})
                                   .def("AUTO"),
                               real("RESI_RELA",
                                    "Relative residual |b - A x| / |b| each solve must reach after iterative "
                                    "refinement, or the run stops naming the residual reached (a singular or too "
                                    "ill-conditioned system); zero or negative: not checked, Newton's residual alone "
                                    "judges (code_aster's default in STAT_NON_LINE, -1). Absent: 1e-6, "
                                    "lunaster's check for every direct solve"),
                               text("MATR_DISTRIBUEE",
                                    "Under mpirun: OUI shares the model among the ranks (Scotch partition of "
                                    "the cells; each rank assembles and keeps the rows of the nodes it owns and "
                                    "gives them to MUMPS as distributed entries); NON gives every rank the whole "
                                    "system (each assembles all of it; MUMPS reads rank 0's copy and still "
                                    "factorises across the ranks), whose values are those of a run without mpirun "
                                    "to round-off. Without mpirun there is one rank and nothing to share. "
                                    "code_aster's default is NON; lunaster's is OUI, the memory of a model "
                                    "beyond one machine")
                                   .into_values({"OUI", "NON"})
                                   .def("OUI"),
                               text("TYPE_RESOL",
                                    "MUMPS's factorisation: AUTO by the system (LDL^T without pivoting for a "
                                    "positive definite one, with pivoting for a symmetric indefinite one: contact "
                                    "or relation multipliers, LU otherwise); NONSYM an LU of every entry (about "
                                    "twice the factor memory); SYMGEN LDL^T with pivoting whatever the system "
                                    "(refused for a system that is not symmetric); SYMDEF LDL^T without pivoting "
                                    "(refused for a system that is not positive definite). The log names the "
                                    "factorisation used when TYPE_RESOL is given")
                                   .into_values({"AUTO", "NONSYM", "SYMGEN", "SYMDEF"})
                                   .def("AUTO"),
                               text("PRETRAITEMENTS",
                                    "What MUMPS does to the matrix before factorising it: AUTO its own choice of "
                                    "scaling and of permutations towards a heavy diagonal (ICNTL(6), (8), (12) "
                                    "automatic); SANS the matrix as assembled (no scaling: NPREC's null-pivot "
                                    "threshold then applies to the entries as they are, where a contact or "
                                    "relation multiplier's pivot, small in absolute terms, counts as null: "
                                    "NPREC = -1 beside it turns that test off)")
                                   .into_values({"AUTO", "SANS"})
                                   .def("AUTO"),
                               text("POSTTRAITEMENTS",
                                    "Iterative refinement of each solve (x += A^-1 (b - A x) on the same "
                                    "factors), with code_aster's MUMPS settings: AUTO up to 4 steps, until the "
                                    "solve is backward stable row by row (|A x - b| <= 1e-14 (|A| |x| + |b|) in "
                                    "every row; on a model shared among MPI ranks, until the relative residual "
                                    "is under 1e-10); SANS none (RESI_RELA then judges the solve straight from "
                                    "the factors); MINI two steps, backward stable or not; FORCE up to 10 steps, "
                                    "backward stable or not. A step that does not lower the residual ends the "
                                    "refinement. The instant's log line says how many steps were taken. Applies "
                                    "to every direct solve of the run")
                                   .into_values({"AUTO", "SANS", "MINI", "FORCE"})
                                   .def("AUTO"),
                               text("ACCELERATION",
                                    "MUMPS's factorisation in full or block low rank, as code_aster runs it on a "
                                    "public MUMPS: AUTO and FR in full rank; LR in block low rank (ICNTL(35) = 1): "
                                    "the off-diagonal blocks of the large fronts keep the rank their singular "
                                    "values leave above LOW_RANK_SEUIL, which makes the factors approximate to "
                                    "about that threshold (POSTTRAITEMENTS' refinement takes each solve back to "
                                    "round-off) and can save factor memory and operations on large 3D systems. "
                                    "The log says how many factor entries the compression kept. FR+, FR++, LR+ "
                                    "and LR++ add settings of the MUMPS consortium's version, not in Debian's: "
                                    "they run as FR or LR, and the log says so")
                                   .into_values({"AUTO", "FR", "FR+", "FR++", "LR", "LR+", "LR++"})
                                   .def("AUTO"),
                               real("LOW_RANK_SEUIL",
                                    "Threshold of the block low-rank factorisation (ACCELERATION = 'LR'; CNTL(7)): "
                                    "a block's singular values below it are dropped; 0 keeps every one (no "
                                    "compression, no loss), 1e-9 to 1e-12 are usual. Negative: the same threshold "
                                    "(its absolute value) with the UCFS variant, compressing before the updates "
                                    "(ICNTL(36) = 1), as in code_aster. Given beside a full-rank ACCELERATION "
                                    "it would do nothing: refused")
                                   .def(0.0),
                               text("MIXER_PRECISION",
                                    "OUI: MUMPS factorises in single precision (half the factor memory, fewer "
                                    "bytes moved), and the iterative refinement of POSTTRAITEMENTS, in double "
                                    "precision on the matrix as assembled, takes each solve to the accuracy "
                                    "asked (RESI_RELA). For systems whose condition number single precision can "
                                    "carry (about 1e6 and below after MUMPS's scaling): beyond, the refinement "
                                    "does not converge and the run stops saying so. The log names the "
                                    "factorisation 'MUMPS in single precision'. NON (default): double precision")
                                   .into_values({"OUI", "NON"})
                                   .def("NON"),
                               real("FILTRAGE_MATRICE",
                                    "Positive: MUMPS factorises the matrix without its entries |a_ij| <= "
                                    "FILTRAGE_MATRICE (|a_ii| + |a_jj|), as code_aster's MUMPS driver filters "
                                    "them: a sparser matrix, approximate factors; the iterative "
                                    "refinement of POSTTRAITEMENTS, on the matrix as assembled, takes each "
                                    "solve to the accuracy asked (RESI_RELA) or the run stops saying so. The "
                                    "log says how many entries were left out. The entries kept may differ "
                                    "from one matrix to the next, and MUMPS analyses again when they do. "
                                    "Below 0.5 (from 0.5 every diagonal entry would go). Zero or negative "
                                    "(default -1): every entry kept")
                                   .def(-1.0)
                                   .below(0.5),
                               elim_lagr({"OUI", "NON", "LAGR2"}, "LAGR2"),
                               integer("PCENT_PIVOT",
                                       "Working space of MUMPS's factorisation beyond its analysis's estimate, in "
                                       "percent (ICNTL(14)): room for the pivots an indefinite system delays. "
                                       "When a factorisation runs short it is doubled and the factorisation "
                                       "redone (three times at most). Given, the log says what "
                                       "the factorisation allocated with it. Absent: MUMPS's default (MUMPS 5.5 "
                                       "on one process: 5 % for an SPD system, 20 % otherwise)")
                                   .range(1, std::nullopt)},
                              {}},
                        Block{"METHODE",
                              {"AUTO", "CHOLMOD", "MULT_FRONT", "LDLT", "MUMPS"},
                              {integer("NPREC",
                                       "Significant digits a pivot may lose before the factorisation calls the "
                                       "matrix singular (a rigid-body mode, a missing condition, a penalty too "
                                       "stiff): CHOLMOD compares each pivot with its diagonal (L_jj^2 <= 10^-NPREC "
                                       "A_jj); MUMPS detects null pivots of an indefinite system below 10^-NPREC "
                                       "in its scaled matrix (ICNTL(24), CNTL(3) = -10^-NPREC) and sets them to "
                                       "1e20 (CNTL(5)), and a positive definite one, which MUMPS does not test, "
                                       "is first factorised by CHOLMOD with the same test. "
                                       "Negative: no test (CHOLMOD still stops on a zero or negative pivot, "
                                       "whatever STOP_SINGULIER says). "
                                       "Also the digits the diagnosis of a failed solve looks for. AUTO's "
                                       "iterative solve of large 3D systems has no pivots")
                                   .def(8LL),
                               text("STOP_SINGULIER",
                                    "OUI: a singular matrix stops the run with the node and component of the "
                                    "pivot. NON: the run goes on with a warning naming them: past weak pivots "
                                    "(CHOLMOD keeps its factor; a zero or negative pivot, which it cannot take, "
                                    "hands the system to MUMPS), past null pivots (MUMPS, which then factorises even a "
                                    "positive definite system as symmetric indefinite to detect them; the "
                                    "solution is zero along them), and past a body no condition holds. "
                                    "Newton's residual still judges each solution")
                                   .into_values({"OUI", "NON"})
                                   .def("OUI")},
                              {}},
                        Block{"METHODE",
                              {"AUTO", "CHOLMOD", "MULT_FRONT", "LDLT", "UMFPACK", "PETSC"},
                              {elim_lagr({"OUI", "NON"}, "NON")},
                              {}},
                        Block{"METHODE",
                              {"MULT_FRONT"},
                              {text("RENUM",
                                    "Fill-reducing ordering of the factorisation (CHOLMOD, or MUMPS/UMFPACK for an "
                                    "indefinite system): METIS the nested dissection of the mesh's node graph; MDA "
                                    "approximate minimum degree (AMD); MD the same AMD (no exact minimum degree "
                                    "here). Absent: lunaster's choice (AMD, and METIS too where it pays on 3D "
                                    "systems). The log names the ordering used")
                                   .into_values({"METIS", "MD", "MDA"})},
                              {}},
                        Block{"METHODE",
                              {"LDLT"},
                              {text("RENUM",
                                    "Ordering of the factorisation (CHOLMOD, or MUMPS/UMFPACK for an indefinite "
                                    "system): RCMK reverse Cuthill-McKee of the mesh's node graph (a profile "
                                    "ordering, as code_aster's LDLT: much more fill than AMD on large models); SANS "
                                    "the equations' own order. Absent: lunaster's choice (AMD, and METIS too where "
                                    "it pays on 3D systems). The log names the ordering used")
                                   .into_values({"RCMK", "SANS"})},
                              {}}}),
      integer("INFO", "Amount of printed information: 1 normal; 2 also prints each Krylov iteration's relative "
                      "residual when SOLVEUR METHODE='PETSC'")
          .into_values({1LL, 2LL})
          .def(1LL),
  };
  // COMP_ELAS is the seed's STAT_NON_LINE spelling; code_aster 17's MECA_NON_LINE has none.
  if (meca_non_line)
    kws.erase(std::remove_if(kws.begin(), kws.end(), [](const Keyword& k) { return k.name == "COMP_ELAS"; }), kws.end());
  return kws;
}

}  // namespace

const CommandSpec& stat_non_line_spec() {
  static const CommandSpec spec = make_command(
      "STAT_NON_LINE", "evol_noli", "Quasi-static nonlinear analysis (Newton, contact)", keywords(false),
      {at_most_one({"COMP_ELAS", "COMPORTEMENT"})});
  return spec;
}

const CommandSpec& meca_non_line_spec() {
  static const CommandSpec spec = make_command(
      "MECA_NON_LINE", "evol_noli",
      "Quasi-static nonlinear analysis, code_aster 17 spelling of STAT_NON_LINE (same engine, same results; "
      "CONTACT=_F(DEFINITION=...))",
      keywords(true), {});
  return spec;
}

}  // namespace lunaster::catalog
