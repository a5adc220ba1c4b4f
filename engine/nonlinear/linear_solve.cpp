#include "engine/nonlinear/linear_solve.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>

#include "engine/nonlinear/sci.hpp"
#include "engine/nonlinear/stopwatch.hpp"
#include "engine/parallel/mpi_runtime.hpp"
#include "engine/solver/backends.hpp"
#include "engine/solver/saddle_solver.hpp"

namespace lunaster::engine {

namespace {

/// A linear solve is accepted when |K du + r| / |r| is below this (after iterative
/// refinement): far above round-off for a well-posed system, far below what a singular
/// one leaves (a rigid-body mode, a contact block without rank). Newton corrects the
/// remaining inaccuracy at its next iteration. A direct solve's own tolerance
/// (NewtonOptions::direct_solve_tolerance) replaces it when given.
constexpr double kSolveTolerance = 1e-6;

/// GMRES with the previous factorisation as preconditioner (a new pairing, same statuses):
/// at most this many iterations, to this relative residual, before refactorising.
constexpr int kKrylovIterations = 30;
constexpr double kKrylovTolerance = 1e-12;

/// A large 3D SPD system: a factorisation fills too much (LinearSolve::choose).
constexpr int kLargeSpd3d = 100000;


}  // namespace

LinearSolve::Backend LinearSolve::choose(MatrixKind kind, int n_free, int dim, bool distributed,
                                        bool definite_stiffness) {
  Backend out;
  if (options_.solver == SolverKind::Petsc) return out.kind = SolverKind::Petsc, out;  // iterative: any kind, as asked
  // A large 3D SPD system: a factorisation fills too much. On the 2.8e5-unknown HEXA8/HEXA20
  // mortar benchmark CHOLMOD took 139 s and 11 GB (its best ordering, METIS on the node graph,
  // still filled 8.8e8 entries), MUMPS 63 s and 6.6 GB, PETSc's CG with BoomerAMG 20-25 s and
  // 1.3 GB. Below, CHOLMOD stays faster. AUTO's CG solves to a relative residual of 1e-12 (the
  // mortar multipliers of that benchmark needed it to stay within 1e-8) in at most 500
  // iterations, and MUMPS takes over if it fails: a choice of ours must not stop a run that a
  // factorisation would have done. A process of an MPI run keeps MUMPS (the same values on
  // every rank, as with CHOLMOD below this size).
  if (options_.auto_solver && options_.solver == SolverKind::Cholmod && kind == MatrixKind::SymmetricPositiveDefinite &&
      dim == 3 && n_free > kLargeSpd3d) {
    const bool iterative = parallel::size() == 1;
    if (!note_said_) out.note = iterative ? BackendNote::AutoIterative : BackendNote::AutoMumps;
    note_said_ = true;
    if (!iterative) return out.kind = SolverKind::Mumps, out;
    options_.iterative = IterativeSettings{};
    options_.iterative.krylov = IterativeSettings::Krylov::CG;
    options_.iterative.preconditioner = IterativeSettings::Preconditioner::Boomer;
    options_.iterative.relative_residual = 1e-12;
    options_.iterative.max_iterations = 500;
    return out.kind = SolverKind::Petsc, out;
  }
  if (options_.solver != SolverKind::Cholmod || kind == MatrixKind::SymmetricPositiveDefinite)
    return out.kind = options_.solver, out;
  // Contact with multipliers gives a symmetric indefinite system: MUMPS (LDLT with
  // pivoting) beat UMFPACK (LU) on it: SSNP121 A refined 16 times, 3.2 s vs 3.6 s and
  // 376 MB vs 608 MB. MUMPS is an MPI library, though, and a process alone pays about 40 ms
  // to start MPI: below about 1e4 unknowns UMFPACK is the faster whole run (SSNP121 A refined
  // 2 times, 0.08 s against 0.11 s; 4 times, 0.19 s against 0.22 s; 8 times, 0.95 s against
  // 0.66 s). Under mpirun MUMPS factorises across the ranks whatever the size.
  constexpr int kSmallIndefinite = 10000;
  const bool small = n_free < kSmallIndefinite && !parallel::launched_by_mpi();
  // A process alone, a symmetric indefinite system: its multipliers' Schur complement on
  // CHOLMOD and GMRES (engine/solver/saddle_solver.hpp), the backend above where that gives
  // way. The SSNP121 3D contact benchmark (1.9e4 unknowns): 1.13e10 operations at CHOLMOD's
  // rate against MUMPS's LDL^T of 1.01e10 at its own, the factorisation phase 0.75x; the
  // same scene at 8.4e3 unknowns, 0.1 s against UMFPACK's 2.0 s. Not on a large 3D system,
  // where CHOLMOD's factor fills too much (above), nor on an indefinite displacements' block
  // (a softening tangent), whose Schur form is not positive definite either.
  saddle_ = kind == MatrixKind::SymmetricIndefinite && definite_stiffness && !parallel::launched_by_mpi() &&
            parallel::size() == 1 && !distributed && !(dim == 3 && n_free > kLargeSpd3d);
  out.kind = small ? SolverKind::Umfpack : SolverKind::Mumps;
  out.fallback = out.kind;
  if (!note_said_) out.note = saddle_ ? BackendNote::SaddleSchur : small ? BackendNote::Umfpack : BackendNote::Mumps;
  note_said_ = true;
  return out;
}

LinearSolver& LinearSolve::backend(SolverKind kind, const Events& events) {
  auto& solver = solvers_[static_cast<int>(kind)];
  if (solver) return *solver;
  IterativeSettings settings = options_.iterative;
  if (options_.krylov_history) settings.history = [this](const std::string& line) { log_.info(line); };
  if (options_.auto_solver && kind == SolverKind::Petsc) {
    solver = make_iterative_with_fallback(settings, SolverKind::Mumps,
                                          [this](const std::string& line) { log_.info(line); });
  } else if (saddle_ && (kind == SolverKind::Mumps || kind == SolverKind::Umfpack)) {
    solver = make_saddle_solver(kind, [this](const std::string& line) { log_.info(line); });
  } else if (kind == SolverKind::Mumps && options_.single_precision) {
    solver = make_mumps_solver(true);
    events({Event::What::SinglePrecision});
  } else {
    solver = make_linear_solver(kind, settings);
  }
  solver->configure(options_.factor);
  return *solver;
}

bool LinearSolve::solved_on_previous(LinearSolver& solver, const FactorState& state, const System& system,
                                     const Vector& rhs, const Events& events, Vector& du, RefinedSolve& accuracy) {
  // REAC_ITER: between two renewals the last factors of this loop solve with the current
  // residual (a modified Newton step, no refinement against a matrix they do not factorise).
  const int iter = system.iteration;
  const bool renew = iter == 0 || (options_.reac_iter > 0 && iter % options_.reac_iter == 0);
  if (!renew && state.factorised && state.n == system.a->rows()) {
    Stopwatch watch(stats_.solve_seconds);
    du = solver.solve(rhs);
    events({Event::What::FactorsReused, &solver, state.iteration});
    return true;
  }
  if (solver.iterative() || system.on_interface || !state.factorised || state.n != system.a->rows() ||
      state.statuses != system.statuses || state.pattern == system.pattern)
    return false;
  // A new pairing with the same statuses: the previous factorisation is a close
  // preconditioner; a few Krylov iterations replace a factorisation when they converge.
  Stopwatch watch(stats_.solve_seconds);
  const KrylovResult k = preconditioned_gmres(system.product, solver, rhs, du, kKrylovIterations, kKrylovTolerance);
  if (k.converged) {
    accuracy.raw_residual = accuracy.residual = k.residual;
    stats_.krylov_iterations += k.iterations;
  }
  Event said{Event::What::KrylovOnPrevious, &solver, iter, k.iterations, k.residual, k.converged};
  events(said);
  return k.converged;
}

void LinearSolve::factorize(LinearSolver& solver, FactorState& state, SolverKind kind, const System& system) {
  // One set of factors alive at a time: the other backends' (e.g. CHOLMOD's of a pass
  // without active contact) are released before this one is built.
  for (int other = 0; other < kSolverKinds; ++other)
    if (other != static_cast<int>(kind) && solvers_[other]) {
      solvers_[other].reset();
      states_[other] = FactorState{};
    }
  try {
    Stopwatch watch(stats_.factorize_seconds);
    state.factorised = false;
    LUNASTER_ASSERT(!system.distributed || solver.takes_distributed(), "a shared model needs a backend that takes it");
    if (solver.iterative() || system.distributed) solver.set_layout(system.layout());
    LUNASTER_ASSERT(holder_ == nullptr, "K_ff was handed to a backend: it cannot be factorised again");
    if (system.observe) system.observe(*system.a, system.kind);
    if (system.takeable) {
      // The system is K_ff itself: a backend that keeps its own copy (PETSc) takes it, and one
      // copy is enough; a direct backend leaves it here.
      if (solver.factorize_taking(*system.takeable, system.kind)) holder_ = &solver;
    } else {
      solver.factorize(*system.a, system.kind);
    }
  } catch (const SolveError& err) {
    if (err.out_of_memory() || err.failure().what == Failure::What::IterativeSolve) throw;
    throw system.diagnose(err);
  }
  ++stats_.factorisations;
  state.factorised = true;
  state.n = static_cast<int>(system.a->rows());
  state.pattern = system.pattern;
  state.statuses = system.statuses;
  state.values_key = system.values_key;
  state.iteration = system.iteration;
}

void LinearSolve::direct_solve(LinearSolver& solver, const System& system, const Vector& rhs, Vector& du,
                               RefinedSolve& accuracy, const Events& events) {
  Stopwatch watch(stats_.solve_seconds);
  // With |A| |x| at hand, every solve above round-off is judged row by row: a relative
  // residual of 8e-11 (under the 1e-10 that asks for refinement without it) left SSNP121 E's
  // LAGS_C 3e-8 off in a two-rank MUMPS run, its multiplier rows far from their own round-off.
  using R = NewtonOptions::Refinement;
  const R policy = options_.refinement;
  // code_aster's MUMPS settings: AUTO ICNTL(10) = 4 with CNTL(2) = 1e-14 (the backward error
  // that stops it), MINI ICNTL(10) = -2 (two steps, no test: both taken, the better iterate
  // kept), FORCE ICNTL(10) = 10 with no backward-error stop. A step that does not lower the
  // residual is not kept.
  const int steps = policy == R::None ? 0 : policy == R::Two ? 2 : policy == R::Force ? 10 : 4;
  const bool stop_when_stable = policy == R::Auto;
  const bool whole = system.whole;
  accuracy = solve_with_refinement(solver, system.product, rhs, du, steps,
                                   !stop_when_stable ? 0.0 : whole ? 1e-14 : 1e-10,
                                   whole && stop_when_stable ? &system.abs_product : nullptr,
                                   options_.direct_solve_tolerance > 0.0 ? options_.direct_solve_tolerance
                                                                         : kSolveTolerance,
                                   system.norm, policy == R::Two);
  // A direct backend that iterates on a factorisation of another matrix (the multipliers'
  // Schur complement) says how many iterations its last solve took.
  if (const int its = solver.iterations(); its > 0) {
    stats_.krylov_iterations += its;
    events({Event::What::DirectIterated, &solver, system.iteration, its, accuracy.residual});
  }
}

Vector LinearSolve::solve(LinearSolver& solver, FactorState& state, SolverKind kind, const System& system,
                          const Vector& rhs, const Events& events, RefinedSolve& accuracy) {
  const bool iterative = solver.iterative();
  const bool same_matrix =
      state.factorised && state.pattern == system.pattern && state.values_key == system.values_key;
  Vector du;
  const bool solved = !same_matrix && solved_on_previous(solver, state, system, rhs, events, du, accuracy);
  if (!solved && !same_matrix) {
    factorize(solver, state, kind, system);
    events({Event::What::Factorised, &solver, system.iteration});
  } else if (same_matrix) {
    events({Event::What::SameMatrix, &solver, system.iteration});
  }
  if (!solved && iterative) {
    // The Krylov solver iterates to its own tolerance and fails when it does not get there:
    // no refinement on top.
    Stopwatch watch(stats_.solve_seconds);
    du = solver.solve(rhs);
    accuracy.raw_residual = accuracy.residual = relative_residual(system.product, du, rhs, system.norm);
    stats_.krylov_iterations += solver.iterations();
    events({Event::What::IterativeSolved, &solver, system.iteration, solver.iterations(), accuracy.residual});
  } else if (!solved) {
    direct_solve(solver, system, rhs, du, accuracy, events);
  }
  ++stats_.newton_iterations;
  stats_.refinement_steps += accuracy.steps;
  // A direct solver may return a "solution" of a singular system without flagging it (MUMPS
  // misses null pivots that are round-off rather than exact zeros): check the solve itself,
  // and locate the rigid-body mode when it did not solve the system.
  const double raw_error = accuracy.raw_residual, solve_error = accuracy.residual;
  stats_.solve_residual_raw = std::max(stats_.solve_residual_raw, raw_error);
  stats_.solve_residual = std::max(stats_.solve_residual, solve_error);
  const double accepted = iterative ? std::max(kSolveTolerance, 1.01 * options_.iterative.relative_residual)
                          : options_.direct_solve_tolerance > 0.0 ? options_.direct_solve_tolerance
                                                                  : std::numeric_limits<double>::infinity();
  if (!(solve_error <= accepted))
    throw system.diagnose(SolveError("the linear solver returned no accurate solution (relative residual of the "
                                     "solve " + sci(raw_error) + ", " + sci(solve_error) +
                                     " after iterative refinement; accepted below " + sci(accepted) + ")"));
  return du;
}

}  // namespace lunaster::engine
