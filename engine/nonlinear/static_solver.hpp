#pragma once
/// Quasi-static incremental solver: Newton iterations per instant, with an
/// optional contact algorithm plugged in through `ContactHook`.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/fields/fields.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

/// Imposed value of one displacement component; `load` indexes the multiplier.
struct DirichletValue { int node; int component; double value; int load; };
/// Pressure on boundary cells (PRES_REP), Pa.
struct PressureLoad { std::vector<int> cells; double pressure; int load; };
/// Nodal force (FORCE_NODALE), N.
struct NodalForce { int node; int component; double value; int load; };

/// Everything imposed on the model; value(t) = value * multipliers[load](t).
struct MechanicalLoads {
  std::vector<DirichletValue> dirichlet;
  std::vector<PressureLoad> pressures;
  std::vector<NodalForce> forces;
  std::vector<std::function<double(double)>> multipliers;  ///< one per load index
};

struct NewtonOptions {
  double resi_glob_rela = 1e-6;  ///< relative residual |r| / |f_ext + reactions|; <= 0: unused
  double resi_glob_maxi = -1.0;  ///< absolute residual (N); <= 0: unused
  int iter_glob_maxi = 10;
  SolverKind solver = SolverKind::Cholmod;  ///< Cholmod gives way to Mumps for systems that are not SPD (logged once)
  /// Matrix policy (code_aster's NEWTON keywords). reac_iter: a new factorisation at Newton
  /// iteration k of a Newton loop (one per instant and per contact pass) when k == 0 or
  /// k % reac_iter == 0; 0 = at k == 0 only. Between two, the last factors solve with the
  /// current residual (a modified Newton). Convergence is always judged on the true residual.
  int reac_iter = 1;
  /// The elastic stiffness alone (no contact terms) instead of the tangent, factorised once
  /// per run: with linear elasticity and a fixed set of Dirichlet equations it never changes.
  /// Not for runs with contact (the multiplier equations would be empty).
  bool elastic_matrix = false;
  int subdivide_levels = 0;  ///< on a Newton failure, split the step this many times at most (SUBD_NIVEAU)
  int subdivide_parts = 4;   ///< sub-steps per split (SUBD_PAS)
};

/// Dirichlet conditions of one instant, eliminated from the system (static_solver.cpp).
struct Constraints;

/// Newton (or a contact loop) did not converge: a smaller step may help.
class ConvergenceError : public SolveError {
 public:
  using SolveError::SolveError;
};

/// Contact algorithm seen by the Newton driver (implemented in engine/contact).
class ContactHook {
 public:
  virtual ~ContactHook() = default;
  /// The Dirichlet conditions of the run, once, before add_dofs (a hook that ties
  /// unknowns together skips the relations these already impose).
  virtual void set_dirichlet(const std::vector<DirichletValue>& /*dirichlet*/) {}
  /// Adds contact unknowns (LAGS_C ...) to the numbering, once, before any step.
  virtual void add_dofs(DofMap& dofs) = 0;
  /// Start of an instant, with the converged displacement of the previous one.
  virtual void begin_step(const Vector& u, const Log& log) = 0;
  /// Adds the contact tangent and residual at iterate u (residual = internal - external).
  virtual void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) = 0;
  /// Called when Newton converged with the current statuses/geometry frozen.
  /// Updates statuses and pairing; returns true when nothing changed (settled).
  virtual bool settle(const Vector& u, const Log& log) = 0;
  /// Kind of the assembled system once contact is in (Lagrange => indefinite).
  virtual MatrixKind matrix_kind() const = 0;
  /// Number of contact points (or slave nodes) currently active. With none, the
  /// bodies must be held by Dirichlet conditions alone: the driver checks it.
  virtual int n_active() const = 0;
  /// Stores contact results (LAGS_C in DEPL is already in u; CONT_NOEU ...).
  virtual void write_fields(const Vector& u, ResultStep& step) const = 0;
};

/// What one run cost, measured by the solver itself (wall seconds, counts).
/// Read through `StaticSolver::stats()`; IMPR_MESURE writes it as a CSV row.
struct SolverStats {
  int n_dofs = 0;             ///< unknowns, contact multipliers included
  int n_free = 0;             ///< unknowns left after eliminating Dirichlet conditions (largest over instants)
  int instants = 0;           ///< converged instants (sub-steps included)
  int newton_iterations = 0;  ///< linear solves, over all instants and contact passes
  int factorisations = 0;     ///< numeric factorisations; fewer than the solves when factors are reused
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
  double resi_glob_rela = 0.0;     ///< RESI_GLOB_RELA reached at the last converged Newton iteration
};

/// Runs the instants in turn from u = 0; returns one ResultStep per instant
/// (nume_ordre 0 = initial state) with DEPL. Throws SolveError on divergence,
/// naming the instant, the loop and the last residuals; steps converged before
/// the failure are available through `converged_steps()`.
class StaticSolver {
 public:
  StaticSolver(const FeModel& model, const MechanicalLoads& loads, NewtonOptions options, ContactHook* contact,
               const Log& log);
  std::vector<ResultStep> run(const std::vector<double>& instants);
  const std::vector<ResultStep>& converged_steps() const { return steps_; }
  const DofMap& dofs() const { return dofs_; }
  /// Cost of the last `run` (also filled when it throws).
  const SolverStats& stats() const { return stats_; }

 private:
  /// Advances u from instant t0 to t1, splitting the step on ConvergenceError.
  void advance(double t0, double t1, int level, Vector& u);
  /// Newton (+ contact loops) at instant t starting from u; throws on failure.
  void solve_instant(double t, Vector& u);
  /// One Newton correction du = -K^-1 r_free on the free equations, K factorised anew or
  /// reused as the matrix policy says; `k` = solves already done in this instant.
  Vector newton_correction(double t, int k, const Constraints& cons, const std::vector<Triplet>& k_contact,
                           const Vector& r_free);
  /// The matrix policy's one decision: factorise at Newton iteration k of an instant?
  bool needs_factorisation(int k, const std::vector<int>& free_index) const;
  /// Backend for a system of this kind: Cholmod gives way to Mumps (said once per run).
  SolverKind backend_for(MatrixKind kind);
  NodalField make_depl(const Vector& u) const;
  SparseMatrix k_full_;
  double k_scale_ = 0.0;  ///< largest stiffness coefficient, for the residual reference
  bool rigid_checked_ = false;  ///< elastic part proven free of rigid-body modes
  bool backend_note_logged_ = false;  ///< the Cholmod -> Mumps substitution was logged in this run

  /// The factors Newton solves with and the reduced matrix they belong to (iterative
  /// refinement needs it). Lives until the matrix policy asks for new ones: within one
  /// Newton loop for the tangent (REAC_ITER), for the whole run for the elastic matrix.
  struct Factorisation {
    std::unique_ptr<LinearSolver> solver;
    SparseMatrix matrix;
    std::vector<int> free_index;  ///< the Dirichlet elimination it was built with
    int iteration = -1;           ///< Newton iteration of its loop where it was computed
  };
  Factorisation factors_;

  const FeModel& model_;
  const MechanicalLoads& loads_;
  NewtonOptions options_;
  ContactHook* contact_;
  const Log& log_;
  DofMap dofs_;
  std::vector<ResultStep> steps_;
  SolverStats stats_;
};

}  // namespace lunaster::engine
