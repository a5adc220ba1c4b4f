#pragma once
/// The linear solve of a Newton iteration (the role of PETSc's KSP in a SNES): the backend for
/// the system's kind, its factorisation kept while the matrix is the same (or reused between
/// REAC_ITER renewals, or as GMRES's preconditioner for a close matrix), iterative refinement
/// and the acceptance of the solve. What it does is reported as events, in order, and as a
/// result: the driver words the log.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/nonlinear/newton_options.hpp"
#include "engine/solver/krylov.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class LinearSolve {
 public:
  /// What a backend last factorised: the system pattern it was for, the statuses, the values.
  /// Lives as long as the factorisation it describes.
  struct FactorState {
    bool factorised = false;
    long pattern = -1;
    int n = -1;
    unsigned long long statuses = 0;
    std::uint64_t values_key = 0;
    int iteration = -1;  ///< Newton iteration of its loop where it was computed
  };

  /// Why the backend is not the one the run named, said once per run.
  enum class BackendNote {
    None,
    AutoIterative,  ///< the automatic choice: PETSc CG + BoomerAMG for a large 3D SPD system
    AutoMumps,      ///< the automatic choice: MUMPS for a large 3D SPD system under mpirun
    SaddleSchur,    ///< CHOLMOD on the multipliers' Schur complement, GMRES on it
    Umfpack,        ///< CHOLMOD cannot factorise this kind: UMFPACK
    Mumps           ///< CHOLMOD cannot factorise this kind: MUMPS
  };
  struct Backend {
    SolverKind kind = SolverKind::Cholmod;
    BackendNote note = BackendNote::None;  ///< set the first time only
    SolverKind fallback = SolverKind::Mumps;  ///< SaddleSchur: the backend if that gives way
  };

  /// One thing the solve did, reported as it happens.
  struct Event {
    enum class What {
      SinglePrecision,      ///< a MUMPS backend made to factorise in single precision
      FactorsReused,        ///< REAC_ITER: the factors of `iteration` solved
      KrylovOnPrevious,     ///< GMRES on the previous factorisation: `iterations`, `residual`, `converged`
      Factorised,           ///< `solver` factorised the system (its notes are the solver's to read)
      SameMatrix,           ///< the matrix is the one last factorised (or preconditioned)
      IterativeSolved,      ///< an iterative backend solved: `iterations`, `residual`
      DirectIterated        ///< a direct backend iterated on a factorisation of another matrix
    } what;
    const LinearSolver* solver = nullptr;
    int iteration = 0, iterations = 0;
    double residual = 0.0;
    bool converged = false;
  };
  using Events = std::function<void(const Event&)>;

  /// The system of one Newton iteration, as the solve sees it.
  struct System {
    const SparseMatrix* a = nullptr;  ///< the matrix handed to a factorisation
    MatrixKind kind = MatrixKind::SymmetricPositiveDefinite;
    long pattern = 0;                 ///< changes with the matrix's pattern
    std::uint64_t values_key = 0;     ///< equal keys, equal matrices
    unsigned long long statuses = 0;  ///< the contact statuses it was built with
    int iteration = 0;                ///< Newton iteration in its loop
    MatrixProduct product;            ///< A x over this rank's equations (collective when shared)
    MatrixProduct abs_product;        ///< |A| |x| (empty: not at hand, the backward error is not judged)
    const VectorNorm* norm = nullptr;  ///< in parts: the owned entries' norm over the ranks
    bool on_interface = false;        ///< solved by the interface solver on its kept reference
    bool whole = true;                ///< A is whole on this process (not shared, not in a backend's hands)
    bool distributed = false;         ///< the system is shared among the ranks
    std::function<SystemLayout()> layout;  ///< the equations' layout, for an iterative or shared backend
    /// A matrix the backend may take rather than copy (K_ff alone, factorised once); null: none.
    SparseMatrix* takeable = nullptr;
    /// Called with each matrix handed to a factorisation (may be empty).
    std::function<void(const SparseMatrix&, MatrixKind)> observe;
    /// A factorisation or the solve's accuracy failed: the error explained (thrown by solve).
    std::function<SolveError(const SolveError&)> diagnose;
  };

  /// `options` is the run's (the automatic choice may set its iterative settings), `stats` its
  /// counters, `log` what the backends write themselves (Krylov histories): all borrowed.
  LinearSolve(NewtonOptions& options, SolverStats& stats, const Log& log)
      : options_(options), stats_(stats), log_(log) {}

  /// The backend for a system of this kind with n_free unknowns. `definite_stiffness`: the
  /// displacements' block is positive definite (false: a softening tangent), so that an
  /// indefinite system may go to the saddle-point backend (Cholesky of that block's Schur form).
  Backend choose(MatrixKind kind, int n_free, int dim, bool distributed, bool definite_stiffness = true);
  /// The backend of this kind, made the first time (one per kind for the run: each keeps its
  /// analysis while the pattern holds).
  LinearSolver& backend(SolverKind kind, const Events& events);
  /// The factor state of backend `kind`.
  FactorState& state(SolverKind kind) { return states_[static_cast<int>(kind)]; }

  /// Solves A du = rhs with `solver` (a backend, or the interface solver with its own state),
  /// factorising when the matrix or the policy asks for it. Throws SolveError (explained by
  /// system.diagnose) when the factorisation fails or the solve misses its accuracy.
  Vector solve(LinearSolver& solver, FactorState& state, SolverKind kind, const System& system, const Vector& rhs,
               const Events& events, RefinedSolve& accuracy);
  /// The backend that took the system's matrix (System::takeable), or null.
  const LinearSolver* holder() const { return holder_; }

 private:
  /// Factorises system.a with solver, unless the previous factorisation solved it by GMRES.
  bool solved_on_previous(LinearSolver& solver, const FactorState& state, const System& system, const Vector& rhs,
                          const Events& events, Vector& du, RefinedSolve& accuracy);
  void factorize(LinearSolver& solver, FactorState& state, SolverKind kind, const System& system);
  void direct_solve(LinearSolver& solver, const System& system, const Vector& rhs, Vector& du,
                    RefinedSolve& accuracy, const Events& events);
  NewtonOptions& options_;
  SolverStats& stats_;
  const Log& log_;
  std::unique_ptr<LinearSolver> solvers_[kSolverKinds];
  FactorState states_[kSolverKinds];
  const LinearSolver* holder_ = nullptr;
  bool note_said_ = false;  ///< the backend note was given in this run
  bool saddle_ = false;     ///< indefinite systems go to the saddle-point backend
};

}  // namespace lunaster::engine
