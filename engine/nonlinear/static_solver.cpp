#include "engine/nonlinear/static_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "engine/core/error.hpp"
#include "engine/nonlinear/failure_diagnosis.hpp"
#include "engine/nonlinear/nodal_forces.hpp"
#include "engine/nonlinear/sci.hpp"
#include "engine/nonlinear/stopwatch.hpp"
#include "engine/nonlinear/time_stepper.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

StaticSolver::StaticSolver(const FeModel& model, const MechanicalLoads& loads, NewtonOptions options,
                           ContactHook* contact, const Log& log)
    : model_(model), loads_(loads), options_(options), contact_(contact), given_contact_(contact), log_(log) {
  LUNASTER_ASSERT(options_.reac_iter >= 0, "reac_iter must be >= 0");
  // The elastic matrix has no contact terms: the multiplier equations would be empty.
  LUNASTER_ASSERT(!(options_.elastic_matrix && contact_), "the elastic matrix is not for runs with contact");
}

void StaticSolver::number_unknowns(std::optional<NodeHalo>& node_halo) {
  in_parts_ = part_ != nullptr;
  RunNumbering numbering =
      engine::number_unknowns(model_, loads_, given_contact_, part_, hook_part_, options_, node_halo);
  dofs_ = std::move(numbering.dofs);
  contact_ = numbering.hook;
  renumbered_contact_ = std::move(numbering.renumbered);
}

std::vector<ResultStep> StaticSolver::run(const std::vector<double>& instants) {
  LUNASTER_ASSERT(!instants.empty(), "no instants");
  std::optional<NodeHalo> node_halo;
  number_unknowns(node_halo);
  const int n = dofs_.n_dofs();
  stats_ = SolverStats{};
  matrix_.clear();
  linear_ = std::make_unique<LinearSolve>(options_, stats_, log_);
  stats_.n_dofs = n;
  distributed_ = in_parts_ || shares_model();
  {
    Stopwatch watch(stats_.assemble_seconds);
    std::vector<int> constrained = Constraints::held_equations(dofs_, loads_, *model_.mesh);
    layout_ = RankLayout();
    if (in_parts_) {
      layout_ = RankLayout::in_parts(*part_, numbered_part(), dofs_, *node_halo, constrained, contact_, log_);
      stats_.n_dofs = static_cast<int>(layout_.unknown_numbers().n_global);
    } else if (distributed_) {
      layout_ = RankLayout::shared(model_, contact_, log_);
    } else if (parallel::size() > 1 && !options_.auto_solver && options_.solver == SolverKind::Mumps) {
      log_.info("model whole on each of the " + std::to_string(parallel::size()) +
                " ranks, as asked: each rank assembles the whole system; MUMPS reads rank 0's copy and "
                "factorises it across the ranks");
    }
    choose_tangent();
    const bool assembled = matrix_.assemble(*tangent_, Vector::Zero(n), constrained, distributed_);
    LUNASTER_ASSERT(assembled, "a behaviour's integration failed at rest");
  }
  k_scale_ = std::max(matrix_.elastic().ff.nonZeros() ? matrix_.elastic().ff.coeffs().cwiseAbs().maxCoeff() : 0.0,
                      matrix_.elastic().c.nonZeros() ? matrix_.elastic().c.coeffs().cwiseAbs().maxCoeff() : 0.0);
  if (distributed_) k_scale_ = parallel::max_over_ranks(k_scale_);
  std::vector<char> displacement(dofs_.n_dofs());
  for (int eq = 0; eq < dofs_.n_dofs(); ++eq) displacement[eq] = dofs_.component_of(eq) <= DZ;
  convergence_ = std::make_unique<ConvergenceTest>(options_, layout_, k_scale_, std::move(displacement));
  return step_through(instants);
}

std::vector<ResultStep> StaticSolver::step_through(const std::vector<double>& instants) {
  Vector u = Vector::Zero(dofs_.n_dofs());
  steps_.clear();
  results_ = std::make_unique<StepResults>(dofs_, model_.mesh->n_nodes(), contact_,
                                          in_parts_ && hook_part_ ? hook_part_->mesh.n_nodes() : model_.mesh->n_nodes());
  if (tangent_->states()) results_->set_points(&model_, tangent_->states(), behaviour_tangent_ ? behaviours_ : nullptr);
  steps_.push_back(results_->step(0, instants[0], u, true));
  const TimeStepper stepper(options_.subdivide_levels, options_.subdivide_parts, contact_, tangent_, log_);
  const TimeStepper::Solve solve = [this](double t, Vector& v) { solve_instant(t, v); };
  const TimeStepper::Commit commit = [this](double t, const Vector& v) {
    ++stats_.instants;
    tangent_->commit();
    if (contact_) contact_->commit_step(v);
    steps_.push_back(results_->step(static_cast<int>(steps_.size()), t, v, false));
  };
  for (size_t i = 1; i < instants.size(); ++i) {
    try {
      stepper.advance(instants[i - 1], instants[i], u, solve, commit);
    } catch (SolveError& err) {
      // Say how far the run got: the converged steps stay available (converged_steps()).
      const ResultStep& last = steps_.back();
      err.add_hint("failed in step " + std::to_string(i) + " of " + std::to_string(instants.size() - 1) + " [" +
                   sci(instants[i - 1]) + ", " + sci(instants[i]) + "]; " + std::to_string(steps_.size() - 1) +
                   " step(s) converged before, the last at instant " + sci(last.inst) + " (stored step " +
                   std::to_string(last.nume_ordre) + ")");
      throw;
    }
  }
  return steps_;
}

SystemLayout StaticSolver::system_layout(const Constraints& cons, const std::vector<int>& condensed,
                                         const std::vector<int>& eliminated) const {
  // In parts with whole contact surfaces the unknowns' nodes are the surfaces' part's; node
  // blocks for PETSc not with a hook's multipliers, which MUMPS alone solves in parts.
  return layout_.system_layout(model_, in_parts_ ? numbered_part().mesh : *model_.mesh, dofs_, cons, condensed,
                               eliminated, renumbered_contact_ == nullptr);
}

bool StaticSolver::shares_model() const {
  // Only when the deck names such a backend: METHODE='AUTO' keeps its choice (CHOLMOD on
  // every rank for an SPD system), so a deck gives the same values under mpirun.
  if (parallel::size() < 2 || options_.auto_solver) return false;
  return (options_.solver == SolverKind::Mumps && options_.share_model) || options_.solver == SolverKind::Petsc;
}

void StaticSolver::choose_tangent() {
  elastic_tangent_ = make_elastic_tangent(model_, dofs_, layout_.owned_nodes());
  behaviour_tangent_ = given_tangent_ || !behaviours_ ? nullptr
                                                      : make_behaviour_tangent(*behaviours_, dofs_, layout_.kind());
  LUNASTER_ASSERT(!behaviour_tangent_ || &behaviours_->model() == &model_, "the behaviours of another model");
  tangent_ = given_tangent_ ? given_tangent_ : behaviour_tangent_ ? behaviour_tangent_.get() : elastic_tangent_.get();
}

Vector StaticSolver::stiffness_times(const Vector& u) const { return matrix_.times(u, layout_, k_ff_holder()); }

Vector StaticSolver::internal_forces(const Vector& u, double t) {
  if (matrix_.constant()) return stiffness_times(u);
  Vector f;
  // K at u from the same integration: the refresh of an iteration that solves keeps it.
  if (!matrix_.refresh_with_forces(u, f)) throw integration_failure(t);
  layout_.complete(f);
  return f;
}

SolveError StaticSolver::diagnose(const Constraints& cons, const SolveError& err, double t) {
  // The elastic stiffness explains a failure; a tangent that follows u may just have lost its
  // stiffness at this iterate: a failed iteration, the step subdivided (TimeStepper).
  if (!matrix_.constant()) throw tangent_solve_failure(err, t);
  FailureDiagnosis::Stiffness stiffness;
  // The failed system with its contact terms, kept before K_ff's values come back in its storage
  // (symmetric contact terms only: an unsymmetric one, friction's, has no stiffness to add).
  const SparseMatrix system = contact_ && matrix_.has_matrix() && contact_->matrix_kind() != MatrixKind::General
                                  ? matrix_.matrix()
                                  : SparseMatrix();
  stiffness.increment = matrix_.increment();
  matrix_.restore();  // K_ff itself, without this iteration's terms
  stiffness.on_no_rank = in_parts_;
  // matrix_.elastic().ff is the whole K_ff unless the model is shared or K_ff went to the backend
  // (also when the backend failed after taking it).
  const bool whole_here =
      !distributed_ && !k_ff_holder() && (matrix_.elastic().ff.nonZeros() > 0 || matrix_.elastic().equation.empty());
  if (whole_here) stiffness.k_ff = &matrix_.elastic().ff, stiffness.system = system.nonZeros() ? &system : nullptr;
  else stiffness.constrained = matrix_.elastic().constrained;
  SolveError explained =
      FailureDiagnosis(model_, options_, contact_ != nullptr).explain(err, t, dofs_, cons.free_index, stiffness);
  if (contact_)
    for (const std::string& h : contact_->failure_hints()) explained.add_hint(h);
  return explained;
}

/// The system of one Newton iteration, K_ff + contact terms restricted to the free
/// equations. Without a contact hook it is matrix_.elastic().ff itself. Otherwise its pattern (K_ff's,
/// contact, a diagonal on every free equation) is built once per contact pattern version,
/// with the position of every contact triplet in it, and becomes K_ff's own; each iteration
/// writes its terms into that one storage and restore_elastic() puts K_ff's values back.
/// Elimination of unknowns by linear relations du_E = A du_R + b (contact_hook.hpp):
/// K' = K_RR + K_RE A + A^T K_ER + A^T K_EE A and r' = (r + K b)_R + A^T (r + K b)_E. Only
/// the columns of K at E are read (K is symmetric), so the cost follows the relations, not
/// the model. The terms of K' beyond K_RR are appended to `triplets` (as contact terms);
/// `r_free` becomes r'. Returns the eliminated equations, whose rows and columns
/// update_system replaces by a unit diagonal.
void StaticSolver::update_system(const Constraints& cons, const std::vector<Triplet>& contact,
                                 const std::vector<int>& condensed, const std::vector<int>& eliminated) {
  const long pattern_before = matrix_.pattern();
  matrix_.begin(cons, dofs_, layout_.owned_nodes());
  if (!contact_) {  // K_ff alone: nothing to copy, nothing to add
    LUNASTER_ASSERT(condensed.empty() && eliminated.empty() && contact.empty(), "no contact hook, no contact terms");
    matrix_.fill_alone();
  } else {
    const long version = contact_->pattern_version();
    interface_.ensure_reference(matrix_.elastic().ff, matrix_.generation(), solve_log_.analysis_said());
    if (interface_.active())
      matrix_.fill_interface(cons, contact, condensed, version, interface_.equations(), interface_.on_interface());
    else
      matrix_.fill_whole(cons, contact, condensed, eliminated, version);
  }
  if (distributed_) matrix_.agree_over_ranks(pattern_before);
}

void StaticSolver::solve_instant(double t, Vector& u) {
  log_.info("instant " + sci(t));
  Instant in;
  in.t = t;
  in.cons = Constraints::at_instant(dofs_, loads_, t, *model_.mesh);
  if (in_parts_) in.cons.take_from_owners(layout_.equation_halo());
  in.cons.impose(u);
  in.f_ext = external_forces(model_, dofs_, loads_, t, distributed_ ? &layout_.node_owner() : nullptr,
                             in_parts_ ? &layout_.equation_halo() : nullptr);
  stats_.n_free = std::max(stats_.n_free, static_cast<int>(layout_.global_free(in.cons.n_free)));
  // The entries this rank answers for in the norms: all of them, or in parts its owned ones.
  in.owned_free = layout_.owned_free(in.cons.n_free);
  if (contact_) {
    Stopwatch watch(stats_.contact_seconds);
    contact_->set_instant(t);
    contact_->begin_step(u, log_);
  }
  const int factorisations_before = stats_.factorisations;
  const int refinements_before = stats_.refinement_steps;
  for (int fixed_point = 0;; ++fixed_point) {
    newton_loop(in, u, fixed_point);
    if (!contact_ || !contact_->has_contact()) break;
    log_.info("contact: " + std::to_string(contact_->n_active()) + " active point(s) in this pass");
    ++stats_.contact_passes;
    bool settled = false;
    {
      Stopwatch watch(stats_.contact_seconds);
      try {
        settled = contact_->settle(u, log_);
      } catch (ConvergenceError& err) {
        err.add_hint("at instant " + sci(t) + ", after " + std::to_string(in.total_newton) +
                     " Newton iteration(s); last residuals: relative " + sci(in.norms.relative) + ", absolute " +
                     sci(in.norms.absolute) + " N");
        err.failure().residuals_known = true;
        err.failure().relative = in.norms.relative, err.failure().absolute = in.norms.absolute;
        throw;
      }
    }
    if (layout_.all_ranks(settled)) break;
  }
  log_.info("  converged in " + std::to_string(in.total_newton) + " Newton iteration(s), " +
            std::to_string(stats_.factorisations - factorisations_before) + " factorisation(s)" +
            (stats_.refinement_steps > refinements_before
                 ? ", " + std::to_string(stats_.refinement_steps - refinements_before) + " refinement step(s)"
                 : std::string()));
}

void StaticSolver::newton_loop(Instant& in, Vector& u, int fixed_point) {
  log_.info("  | iter |  relative resid. |  absolute resid. |");
  in.carried_residual = Vector();
  in.norms = ResidualNorms{};
  for (int iter = 0; iter <= options_.iter_glob_maxi; ++iter) {
    std::vector<Triplet> k_contact;
    Vector residual, r_free;
    bool tangent_pending = false;
    if (converged_at(in, u, iter, residual, r_free, k_contact, tangent_pending)) return;
    if (iter == options_.iter_glob_maxi) break;
    if (tangent_pending) {
      Stopwatch watch(stats_.contact_seconds);
      Vector again = Vector::Zero(dofs_.n_dofs());  // the residual is in `residual` already
      contact_->add_to_system(u, k_contact, again);
    }
    newton_step(in, u, iter, residual, r_free, k_contact);
    ++in.total_newton;
  }
  ConvergenceError err("Newton did not converge at instant " + sci(in.t) + " within " +
                           std::to_string(options_.iter_glob_maxi) + " iterations",
                       {"last residuals: relative " + sci(in.norms.relative) + ", absolute " +
                            sci(in.norms.absolute) + " N",
                        "loop: Newton (contact/geometry fixed-point pass " + std::to_string(fixed_point) + ")"});
  if (contact_)
    for (const std::string& h : contact_->failure_hints()) err.add_hint(h);
  Failure& f = err.failure();
  f.what = Failure::What::NewtonIterations;
  f.limit = options_.iter_glob_maxi;
  f.residuals_known = true, f.relative = in.norms.relative, f.absolute = in.norms.absolute;
  throw err;
}

bool StaticSolver::converged_at(Instant& in, const Vector& u, int iter, Vector& residual, Vector& r_free,
                                std::vector<Triplet>& k_contact, bool& tangent_pending) {
  if (in.carried_residual.size() == dofs_.n_dofs()) {
    residual.swap(in.carried_residual);
    in.carried_residual = Vector();
  } else {
    Stopwatch watch(stats_.assemble_seconds);
    residual = internal_forces(u, in.t) - in.f_ext;
  }
  // The residual may converge from the second iteration on, and in a pass after the first
  // (a new pairing or new statuses) already at its start: a hook that gives its residual
  // alone gives it first, and its tangent only for an iteration that solves.
  const bool may_converge = iter > 0 || in.last_converged_maxi >= 0.0;
  if (contact_) {
    Stopwatch watch(stats_.contact_seconds);
    tangent_pending = may_converge && contact_->add_residual(u, residual);
    if (!tangent_pending) contact_->add_to_system(u, k_contact, residual);
  }
  in.norms = convergence_->measure(in.cons, residual, in.f_ext, u, in.owned_free, r_free);
  char line[96];
  std::snprintf(line, sizeof line, "  | %4d |   %14.6e |   %14.6e |", iter, in.norms.relative, in.norms.absolute);
  log_.info(line);
  if (!std::isfinite(in.norms.absolute)) throw ConvergenceError("the residual became non-finite at instant " + sci(in.t));
  // In parts every rank pairs the whole surfaces alike; the ranks still decide together.
  const bool contact_ok = !contact_ || layout_.all_ranks(contact_->newton_converged());
  if (!convergence_->converged(in.norms, iter, in.last_converged_maxi, contact_ok)) return false;
  if (iter == 0) log_.info("  the new pairing or statuses leave the residual as it was: no solve in this pass");
  in.last_converged_maxi = in.norms.absolute;
  stats_.resi_glob_rela = in.norms.relative;
  return true;
}

void StaticSolver::check_bodies_held(const Instant& in, const SystemTerms& terms, SolverKind backend) {
  // With no contact point active, the bodies must be held by Dirichlet conditions (and
  // relations) alone. Checked once, before any factorisation (FailureDiagnosis::check_held):
  // from the geometry, except in parts (a part alone may look unheld); then by a Cholesky
  // factorisation of K_ff for UMFPACK and MUMPS, which return some solution of a singular but
  // consistent system. CHOLMOD's own factorisation stops on such a system (diagnosed; a run
  // told to go on past singular pivots is warned instead), the interface solver's reference is
  // that factorisation, an iterative backend chosen because factorising does not fit skips it,
  // and so does a shared model, which would need the whole stiffness on one rank.
  if (rigid_checked_ || (contact_ && contact_->n_active() != 0)) return;
  FailureDiagnosis::HeldCheck check;
  // Every unknown of a relation (the hook's and the eliminations'): counted as holding.
  check.related = contact_ ? contact_->related_equations() : std::vector<int>{};
  // A body that only the hook's relations hold leaves K_ff singular, rightly: the mechanism
  // check of K_ff alone is for runs whose every body the Dirichlet conditions hold.
  const bool held_by_relations = !check.related.empty();
  for (const Elimination& e : *terms.eliminated) {
    check.related.push_back(e.eq);
    for (const auto& term : e.terms) check.related.push_back(term.first);
  }
  check.geometry = !in_parts_;
  check.factorise = !held_by_relations && !interface_.active() && backend != SolverKind::Cholmod &&
                    matrix_.positive_definite() &&  // a softening K_ff's negative pivot is no mechanism
                    backend != SolverKind::Petsc && !distributed_ && options_.factor.singularity.digits >= 0;
  const auto k_ff_alone = [&]() -> const SparseMatrix& {
    matrix_.restore();  // K_ff itself, without this iteration's terms
    return matrix_.elastic().ff;
  };
  {
    Stopwatch watch(stats_.assemble_seconds);
    const bool restored = FailureDiagnosis(model_, options_, contact_ != nullptr)
                              .check_held(dofs_, in.cons.free_index, in.t, check, k_ff_alone, log_);
    if (restored) update_system(in.cons, *terms.contact, *terms.condensed, terms.eliminated_eqs);  // the terms again
  }
  rigid_checked_ = true;
}

void StaticSolver::newton_step(Instant& in, Vector& u, int iter, Vector& residual, Vector& r_free,
                               std::vector<Triplet>& k_contact) {
  const Constraints& cons = in.cons;
  if (!matrix_.constant()) {
    Stopwatch watch(stats_.assemble_seconds);
    if (!matrix_.refresh(u)) throw integration_failure(in.t);  // a tangent that follows u: K_ff at this iterate
  }
  static const std::vector<int> no_equations;
  static const std::vector<Elimination> no_eliminations;
  SystemTerms terms;
  terms.contact = &k_contact;
  terms.condensed = contact_ ? &contact_->condensed_equations() : &no_equations;
  terms.eliminated = contact_ ? &contact_->eliminations() : &no_eliminations;
  if (!terms.eliminated->empty()) {
    Stopwatch watch(stats_.assemble_seconds);
    terms.eliminated_eqs =
        cons.eliminate(*terms.eliminated, matrix_.columns(cons, *terms.eliminated, layout_, model_, dofs_, part_),
                        residual, k_contact, r_free);
  }
  if (distributed_) {
    // The hook built the terms of the points that touch this rank's columns, which also
    // reach other ranks' columns: this rank keeps its own.
    k_contact.erase(std::remove_if(k_contact.begin(), k_contact.end(),
                                   [this](const Triplet& tr) { return !(*layout_.owned_nodes())[dofs_.node_of(tr.col())]; }),
                    k_contact.end());
  }
  if (contact_)
    interface_.decide(cons, k_contact, !terms.eliminated_eqs.empty(), *contact_, dofs_, matrix_.elastic().ff,
                      options_.auto_solver && options_.solver == SolverKind::Cholmod && !distributed_ &&
                          matrix_.constant());
  {
    Stopwatch watch(stats_.assemble_seconds);
    update_system(cons, k_contact, *terms.condensed, terms.eliminated_eqs);
    stats_.system_entries = matrix_.matrix().nonZeros();
  }
  // matrix_.elastic().ff is K_ff again when this iteration ends, however it ends (the next
  // residual, a diagnosis, a subdivided step read it).
  struct RestoreElastic {
    StaticSolver* self;
    ~RestoreElastic() { self->matrix_.restore(); }
  } restore_at_end{this};
  // The system of this iteration: the contact law may condense its multipliers out
  // (then it is SPD), and says which kind of matrix is left.
  const MatrixKind kind = matrix_.kind(contact_ ? contact_->matrix_kind() : MatrixKind::SymmetricPositiveDefinite);
  // (The interface solver is CHOLMOD's factorisation of K_ff: no other backend is chosen.)
  const SolverKind backend = interface_.active() ? SolverKind::Cholmod : choose_backend(kind);
  check_bodies_held(in, terms, backend);
  // The contact terms are in the system's storage now: their triplets (5.5e6 of them, 88 MB,
  // on the refined mortar case) go before the factorisation or the preconditioner is built.
  std::vector<Triplet>().swap(k_contact);
  // Condensed unknowns: decoupled rows (unit diagonal, zero right-hand side), set by recover().
  for (int eq : *terms.condensed)
    if (cons.free_index[eq] >= 0) r_free[cons.free_index[eq]] = 0.0;
  RefinedSolve accuracy;
  Vector du = solve_system(in, iter, kind, backend, terms, r_free, accuracy);
  apply_increment(in, du, accuracy, terms, residual, u);
}

Vector StaticSolver::solve_system(const Instant& in, int iter, MatrixKind kind, SolverKind backend,
                                  const SystemTerms& terms, const Vector& r_free, RefinedSolve& accuracy) {
  const Constraints& cons = in.cons;
  const SparseMatrix& a = matrix_.matrix();
  const bool via_interface = interface_.active();
  const bool a_is_k_ff = !contact_ && &a == &matrix_.elastic().ff;
  // In parts, the residuals of a solve are measured on the owned entries over the ranks.
  const int n_owned_free = in.owned_free;
  const VectorNorm owned_norm = [n_owned_free](const Vector& v) {
    double squares = v.head(n_owned_free).squaredNorm();
    parallel::sum_over_ranks(&squares, 1);
    return std::sqrt(squares);
  };
  LinearSolve::System system;
  system.a = &a;
  system.kind = kind;
  system.pattern = matrix_.pattern();
  system.values_key = matrix_.values_key();
  system.statuses = contact_ ? contact_->status_key() : 0ULL;
  system.iteration = iter;
  system.product = system_product(a, a_is_k_ff);
  // |A| |x| for the backward error (not with a shared model or K_ff in PETSc's hands).
  system.abs_product = [&a, this](const Vector& x) -> Vector {
    Vector y = Vector::Zero(x.size());
    add_abs_product(a, x, y);
    if (matrix_.increment()) add_abs_product(matrix_.elastic().ff, x, y);
    return y;
  };
  system.norm = in_parts_ ? &owned_norm : nullptr;
  system.on_interface = via_interface;
  system.whole = !distributed_ && !k_ff_holder();
  system.distributed = distributed_;
  system.layout = [this, &cons, &terms] { return system_layout(cons, *terms.condensed, terms.eliminated_eqs); };
  if (&a == &matrix_.elastic().ff && !contact_ && matrix_.constant()) system.takeable = &matrix_.elastic().ff;
  if (options_.observe_factorisation && !via_interface)
    system.observe = [this](const SparseMatrix& m, MatrixKind k) {
      options_.observe_factorisation(m, k, matrix_.elastic().equation);
    };
  system.diagnose = [this, &in](const SolveError& err) { return diagnose(in.cons, err, in.t); };
  SolveLog::Where where{in.t, model_.mesh, &dofs_, &cons.free_index,
                        via_interface ? static_cast<int>(interface_.equations().size()) : 0};
  const LinearSolve::Events events = [this, &where](const LinearSolve::Event& e) { solve_log_.event(e, where); };
  LinearSolver& solver = via_interface ? interface_.solver() : linear_->backend(backend, events);
  LinearSolve::FactorState& state = via_interface ? interface_.state() : linear_->state(backend);
  return linear_->solve(solver, state, backend, system, -r_free, events, accuracy);
}

MatrixProduct StaticSolver::system_product(const SparseMatrix& a, bool a_is_k_ff) const {
  // A x for the accuracy of a solve: this rank's columns of a, summed over the ranks; the
  // backend's product once K_ff is in its hands. Without contact a is K_ff itself, with its
  // own product; with contact terms it may hold condensed or eliminated rows, which are not
  // symmetric.
  return [&a, a_is_k_ff, this](const Vector& x) -> Vector {
    Vector y;
    const LinearSolver* holder = k_ff_holder();
    if (in_parts_) {
      // The backend holding K_ff gives the owned rows whole. Otherwise x's owned entries
      // are the solve's: its ghosts take their owners' before the product, whose owned
      // entries are complete once the ranks' shares are summed into them.
      if (holder && holder->multiply(x, y)) return y;
      Vector whole_x = x;
      layout_.free_halo().copy_to_ghosts(whole_x.data(), 1);
      y = a * whole_x;
      layout_.free_halo().add_to_owners(y.data(), 1);
      return y;
    }
    if (holder && holder->multiply(x, y)) return y;
    y = a_is_k_ff ? matrix_.elastic().ff_times(x) : Vector(a * x);
    if (matrix_.increment()) y += matrix_.elastic().ff_times(x);  // a is C: the system is K_ff + C
    if (distributed_) parallel::sum_over_ranks(y.data(), y.size());
    return y;
  };
}

void StaticSolver::apply_increment(Instant& in, Vector& du, const RefinedSolve& accuracy, const SystemTerms& terms,
                                   Vector& residual, Vector& u) {
  const Constraints& cons = in.cons;
  const int n = dofs_.n_dofs();
  if (in_parts_) layout_.free_halo().copy_to_ghosts(du.data(), 1);  // the solve gave the owned values
  for (int eq = 0; eq < n; ++eq)
    if (cons.free_index[eq] >= 0) u[eq] += du[cons.free_index[eq]];
  // Without contact or relations the residual is linear in u, and neither f nor u_C move
  // within the instant: the next residual is this one plus K du. Its free rows are the
  // solve's own A du - b (A = K_ff, b = -r_F), its constrained rows cost K(C, F) du; the
  // product of K with u for the next iteration is saved (a third of an elastic instant's
  // products). Not from a residual already near round-off: A du - b would then be the
  // round-off of a tiny correction, far below that of K u - f, and report a state more
  // exact than the stored u can be.
  constexpr double kCarriedAbove = 1e-8;
  const bool a_is_k_ff = !contact_ && &matrix_.matrix() == &matrix_.elastic().ff;
  if (matrix_.constant() && !contact_ && terms.eliminated->empty() && terms.condensed->empty() && a_is_k_ff && !distributed_ &&
      !k_ff_holder() && accuracy.ax_minus_b.size() == cons.n_free && in.norms.relative > kCarriedAbove) {
    in.carried_residual = std::move(residual);
    for (int eq = 0; eq < n; ++eq)
      if (cons.free_index[eq] >= 0) in.carried_residual[eq] = accuracy.ax_minus_b[cons.free_index[eq]];
    matrix_.elastic().add_constrained_rows(du, in.carried_residual);
  }
  cons.recover(*terms.eliminated, du, u);
  if (!terms.condensed->empty()) {
    Stopwatch watch(stats_.contact_seconds);
    contact_->recover(u);
  }
}

SolverKind StaticSolver::choose_backend(MatrixKind kind) {
  const auto chosen = linear_->choose(kind, stats_.n_free, model_.dim, distributed_, matrix_.positive_definite());
  solve_log_.backend(chosen, kind, stats_.n_free);
  return chosen.kind;
}

}  // namespace lunaster::engine
