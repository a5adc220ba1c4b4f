#pragma once
/// What a quasi-static run is asked (the Newton and linear-solver options) and what it
/// cost (its statistics): read by the driver's parts and by commands/.
#include <functional>
#include <vector>

#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

struct NewtonOptions {
  double resi_glob_rela = 1e-6;  ///< relative residual |r| / |f_ext + reactions|; <= 0: unused
  double resi_glob_maxi = -1.0;  ///< absolute residual (N); <= 0: unused
  int iter_glob_maxi = 10;
  SolverKind solver = SolverKind::Cholmod;  ///< Cholmod gives way to Mumps for systems that are not SPD (logged once)
  /// The deck left the choice to lunaster (METHODE='AUTO'): large 3D SPD systems also go to
  /// Mumps, whose nested-dissection orderings fill less there (logged once).
  bool auto_solver = false;
  /// Matrix policy (code_aster's NEWTON keywords). reac_iter: the factors may be renewed at
  /// Newton iteration k of a Newton loop (one per instant and per contact pass) when k == 0
  /// or k % reac_iter == 0; 0 = at k == 0 only. Between two, the last factors solve with the
  /// current residual (a modified Newton). Convergence is always judged on the true residual.
  /// Whatever the policy, a matrix equal to the one last factorised is not factorised again.
  int reac_iter = 1;
  /// The elastic stiffness alone (no contact terms) instead of the tangent. With linear
  /// elasticity, the only behaviour, it is the tangent: factorised once per run either way.
  /// Not for runs with contact (the multiplier equations would be empty).
  bool elastic_matrix = false;
  /// Under mpirun, whether a deck that names MUMPS shares the model among the ranks
  /// (SOLVEUR MATR_DISTRIBUEE='OUI', the default) or gives every rank the whole system ('NON').
  /// PETSc always shares it.
  bool share_model = true;
  /// SolverKind::Petsc: the Krylov method, preconditioner and tolerance.
  IterativeSettings iterative;
  /// How the direct backends analyse and factorise (SOLVEUR RENUM, NPREC, STOP_SINGULIER and,
  /// for MUMPS, GESTION_MEMOIRE, PCENT_PIVOT, PRETRAITEMENTS, ACCELERATION, LOW_RANK_SEUIL,
  /// TYPE_RESOL). Its singularity test also says whether a body that no condition holds stops
  /// the run: not stopping lets it through with a warning, the factorisation then choosing
  /// its position.
  FactorSettings factor;
  /// The relative residual |A du - b| / |b| a direct solve must reach after iterative
  /// refinement (code_aster's SOLVEUR RESI_RELA of MUMPS); <= 0: not checked, Newton's
  /// residual alone judges. Iterative backends keep their own tolerance.
  double direct_solve_tolerance = 1e-6;
  /// Iterative refinement of the direct solves (code_aster's SOLVEUR POSTTRAITEMENTS of MUMPS).
  /// Auto: up to 4 steps, until the solve is backward stable row by row (or no step gains);
  /// None: none; Two: two steps, backward stable or not; Force: up to 10 steps, backward stable
  /// or not. A step is kept only while it lowers the residual.
  enum class Refinement { Auto, None, Two, Force } refinement = Refinement::Auto;
  /// MUMPS factorises in single precision (code_aster's SOLVEUR MIXER_PRECISION = 'OUI'): half
  /// the factor memory; the refinement of each solve, in double precision, makes up the rest.
  bool single_precision = false;
  /// Print each Krylov iteration's residual in the log (code_aster's INFO=2).
  bool krylov_history = false;
  int subdivide_levels = 0;  ///< on a Newton failure, split the step this many times at most
  int subdivide_parts = 4;   ///< sub-steps per split
  /// Called with each matrix handed to a sparse factorisation, its kind, and per column the
  /// equation it stands for (what tests read: the symmetry of a condensed contact system).
  /// Not called for the interface solver's dense Schur complements; with a shared model, a
  /// holds this rank's columns. Empty: nothing called.
  std::function<void(const SparseMatrix& a, MatrixKind kind, const std::vector<int>& equation)> observe_factorisation;
};

/// What one run cost, measured by the solver itself (wall seconds, counts).
/// Read through `StaticSolver::stats()`; IMPR_MESURE writes it as a CSV row.
struct SolverStats {
  int n_dofs = 0;             ///< unknowns, contact multipliers included
  int n_free = 0;             ///< unknowns left after eliminating Dirichlet conditions (largest over instants)
  int instants = 0;           ///< converged instants (sub-steps included)
  int newton_iterations = 0;  ///< linear solves, over all instants and contact passes
  int contact_passes = 0;     ///< contact status/geometry fixed-point passes (calls to settle)
  double assemble_seconds = 0.0;   ///< elastic stiffness, residuals, reduced matrices
  double contact_seconds = 0.0;    ///< contact hook: pairing, statuses, contact terms
  double factorize_seconds = 0.0;  ///< sparse factorisations
  double solve_seconds = 0.0;      ///< forward/back substitutions
  /// Accuracy of the linear solves: largest relative residual |K du + r| / |r| of one
  /// solve, straight from the factorisation and after iterative refinement. The first
  /// grows with the condition number (a stiff penalty, a large COEF_CONT): it shows where
  /// the linear solver starts to lose accuracy, before any run fails.
  double solve_residual_raw = 0.0;
  double solve_residual = 0.0;
  int refinement_steps = 0;        ///< extra solves spent on iterative refinement
  int factorisations = 0;          ///< numeric factorisations (a solve may reuse the last one)
  /// Equations of the contact surfaces when the contact passes were solved on the elastic
  /// factorisation kept for the run (their Schur complement factorised per pass); 0: not.
  int interface_equations = 0;
  int krylov_iterations = 0;       ///< Krylov iterations: on a previous factorisation, of an iterative solver, or on the multipliers' Schur complement
  long system_entries = 0;         ///< stored entries of the last system matrix (this rank's columns)
  double resi_glob_rela = 0.0;     ///< RESI_GLOB_RELA reached at the last converged Newton iteration
};

}  // namespace lunaster::engine
