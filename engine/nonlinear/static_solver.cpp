#include "engine/nonlinear/static_solver.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>

#include "engine/assembly/assembly.hpp"
#include "engine/core/error.hpp"
#include "engine/nonlinear/reduction.hpp"
#include "engine/nonlinear/rigid_body.hpp"

namespace lunaster::engine {

namespace {

/// Adds the wall time of its scope to a SolverStats counter.
class Stopwatch {
 public:
  explicit Stopwatch(double& seconds) : seconds_(seconds), t0_(std::chrono::steady_clock::now()) {}
  ~Stopwatch() { seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(); }
  Stopwatch(const Stopwatch&) = delete;
  Stopwatch& operator=(const Stopwatch&) = delete;

 private:
  double& seconds_;
  std::chrono::steady_clock::time_point t0_;
};

double inf_norm(const Vector& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6e", v);
  return buf;
}

/// A linear solve is accepted when |K du + r| / |r| is below this (after iterative
/// refinement): far above round-off for a well-posed system, far below what a singular
/// one leaves (a rigid-body mode, a contact block without rank). Newton corrects the
/// remaining inaccuracy at its next iteration.
constexpr double kSolveTolerance = 1e-6;

}  // namespace

/// Dirichlet conditions at one instant, applied by elimination.
struct Constraints {
  std::vector<int> free_index;   ///< per equation: index in the reduced system, -1 if constrained
  std::vector<int> constrained;  ///< constrained equations
  std::vector<double> values;    ///< imposed value per constrained equation
  int n_free = 0;
};

namespace {

Constraints build_constraints(const DofMap& dofs, const MechanicalLoads& loads, double t, const Mesh& mesh) {
  Constraints c;
  c.free_index.assign(dofs.n_dofs(), 0);
  std::map<int, double> imposed;
  for (const auto& d : loads.dirichlet) {
    const int eq = dofs.dof(d.node, d.component);
    if (eq < 0)
      throw DeckError("imposed " + std::string(component_name(d.component)) + " on node " + mesh.node_names[d.node] +
                      ", which carries no such unknown in the model");
    imposed[eq] = d.value * loads.multipliers.at(d.load)(t);
  }
  for (const auto& [eq, value] : imposed) {
    c.free_index[eq] = -1;
    c.constrained.push_back(eq);
    c.values.push_back(value);
  }
  for (int eq = 0; eq < dofs.n_dofs(); ++eq)
    if (c.free_index[eq] == 0) c.free_index[eq] = c.n_free++;
  return c;
}

Vector external_forces(const FeModel& model, const DofMap& dofs, const MechanicalLoads& loads, double t) {
  Vector f = Vector::Zero(dofs.n_dofs());
  for (const auto& p : loads.pressures)
    assemble_pressure(*model.mesh, model.dim, p.cells, p.pressure * loads.multipliers.at(p.load)(t), dofs, f);
  for (const auto& fn : loads.forces) {
    const int eq = dofs.dof(fn.node, fn.component);
    if (eq < 0)
      throw DeckError("nodal force " + std::string(component_name(fn.component)) + " on node " +
                      model.mesh->node_names[fn.node] + ", which carries no such unknown in the model");
    f[eq] += fn.value * loads.multipliers.at(fn.load)(t);
  }
  return f;
}

}  // namespace

StaticSolver::StaticSolver(const FeModel& model, const MechanicalLoads& loads, NewtonOptions options,
                           ContactHook* contact, const Log& log)
    : model_(model), loads_(loads), options_(options), contact_(contact), log_(log) {
  LUNASTER_ASSERT(options_.reac_iter >= 0, "reac_iter must be >= 0");
  // The elastic matrix has no contact terms: the multiplier equations would be empty.
  LUNASTER_ASSERT(!(options_.elastic_matrix && contact_), "the elastic matrix is not for runs with contact");
}

NodalField StaticSolver::make_depl(const Vector& u) const {
  std::vector<std::string> cmps = {"DX", "DY"};
  std::vector<int> ids = {DX, DY};
  if (model_.dim == 3) { cmps.push_back("DZ"); ids.push_back(DZ); }
  bool has_lagrange = false;
  for (int eq = 0; eq < dofs_.n_dofs() && !has_lagrange; ++eq) has_lagrange = dofs_.component_of(eq) == LAGS_C;
  if (has_lagrange) { cmps.push_back("LAGS_C"); ids.push_back(LAGS_C); }
  const Mesh& mesh = *model_.mesh;
  NodalField depl(cmps, mesh.n_nodes());
  for (int node = 0; node < mesh.n_nodes(); ++node)
    for (size_t c = 0; c < ids.size(); ++c) {
      const int eq = dofs_.dof(node, ids[c]);
      if (eq >= 0) depl.set(node, static_cast<int>(c), u[eq]);
    }
  return depl;
}

std::vector<ResultStep> StaticSolver::run(const std::vector<double>& instants) {
  LUNASTER_ASSERT(!instants.empty(), "no instants");
  dofs_ = DofMap(*model_.mesh, model_.volume_cells(), model_.dim);
  if (contact_) {
    contact_->set_dirichlet(loads_.dirichlet);
    contact_->add_dofs(dofs_);
  }
  const int n = dofs_.n_dofs();
  stats_ = SolverStats{};
  stats_.n_dofs = n;
  factors_ = Factorisation{};
  backend_note_logged_ = false;
  {
    Stopwatch watch(stats_.assemble_seconds);
    std::vector<Triplet> triplets;
    assemble_stiffness(model_, dofs_, triplets);
    k_full_ = SparseMatrix(n, n);
    k_full_.setFromTriplets(triplets.begin(), triplets.end());
  }  // the triplets are freed here: only the compressed matrix is kept
  k_scale_ = k_full_.nonZeros() ? k_full_.coeffs().cwiseAbs().maxCoeff() : 0.0;

  Vector u = Vector::Zero(n);
  steps_.clear();
  ResultStep initial;
  initial.nume_ordre = 0;
  initial.inst = instants[0];
  initial.nodal["DEPL"] = make_depl(u);
  steps_.push_back(std::move(initial));
  for (size_t i = 1; i < instants.size(); ++i) {
    try {
      advance(instants[i - 1], instants[i], 0, u);
    } catch (SolveError& err) {
      // Say how far the run got: the converged steps stay available (converged_steps()).
      const ResultStep& last = steps_.back();
      err.add_hint("failed in step " + std::to_string(i) + " of " + std::to_string(instants.size() - 1) + " [" +
                   sci(instants[i - 1]) + ", " + sci(instants[i]) + "]; " + std::to_string(steps_.size() - 1) +
                   " step(s) converged before, the last at instant " + sci(last.inst) + " (NUME_ORDRE " +
                   std::to_string(last.nume_ordre) + ")");
      throw;
    }
  }
  return steps_;
}

void StaticSolver::advance(double t0, double t1, int level, Vector& u) {
  Vector trial = u;
  try {
    solve_instant(t1, trial);
  } catch (const ConvergenceError& err) {
    if (level >= options_.subdivide_levels) {
      if (options_.subdivide_levels == 0) throw;
      ConvergenceError final(err.message(), err.hints());
      final.add_hint("step [" + sci(t0) + ", " + sci(t1) + "] still failed after " + std::to_string(level) +
                     " subdivision level(s) (SUBD_NIVEAU)");
      throw final;
    }
    log_.warning("step to instant " + sci(t1) + " failed (" + err.message() + "); splitting it into " +
                 std::to_string(options_.subdivide_parts) + " sub-steps (level " + std::to_string(level + 1) + ")");
    double ta = t0;
    for (int k = 1; k <= options_.subdivide_parts; ++k) {
      const double tb = k == options_.subdivide_parts ? t1 : t0 + (t1 - t0) * k / options_.subdivide_parts;
      advance(ta, tb, level + 1, u);
      ta = tb;
    }
    return;
  }
  u = trial;
  ++stats_.instants;
  ResultStep result;
  result.nume_ordre = static_cast<int>(steps_.size());
  result.inst = t1;
  result.nodal["DEPL"] = make_depl(u);
  if (contact_) contact_->write_fields(u, result);
  steps_.push_back(std::move(result));
}

void StaticSolver::solve_instant(double t, Vector& u) {
  const int n = dofs_.n_dofs();
  log_.info("Instant de calcul: " + sci(t));
  const Constraints cons = build_constraints(dofs_, loads_, t, *model_.mesh);
  for (size_t i = 0; i < cons.constrained.size(); ++i) u[cons.constrained[i]] = cons.values[i];
  const Vector f_ext = external_forces(model_, dofs_, loads_, t);
  stats_.n_free = std::max(stats_.n_free, cons.n_free);
  if (contact_) {
    Stopwatch watch(stats_.contact_seconds);
    contact_->begin_step(u, log_);
  }

  if (!options_.elastic_matrix) factors_ = Factorisation{};  // the tangent is rebuilt at each instant
  const int factorisations_before = stats_.factorisations;

  int total_newton = 0;
  for (int fixed_point = 0;; ++fixed_point) {
    bool converged = false;
    double resi_rela = 0.0, resi_maxi = 0.0;
    log_.info("  | ITER |  RESI_GLOB_RELA |  RESI_GLOB_MAXI |");
    for (int iter = 0; iter <= options_.iter_glob_maxi; ++iter) {
      std::vector<Triplet> k_contact;
      Vector residual;
      {
        Stopwatch watch(stats_.assemble_seconds);
        residual = k_full_ * u - f_ext;
      }
      if (contact_) {
        Stopwatch watch(stats_.contact_seconds);
        contact_->add_to_system(u, k_contact, residual);
      }
      // RESI_GLOB_RELA as code_aster: free residual over the largest load or reaction.
      double denom = inf_norm(f_ext);
      Vector r_free(cons.n_free);
      for (int eq = 0; eq < n; ++eq) {
        const int k = cons.free_index[eq];
        if (k >= 0) r_free[k] = residual[eq];
        else denom = std::max(denom, std::abs(residual[eq]));
      }
      resi_maxi = inf_norm(r_free);
      // A load step where loads and reactions vanish (a body moving rigidly before
      // contact closes) has no natural reference: fall back to the size of the
      // terms that make up the internal forces, so that round-off counts as converged.
      denom = std::max(denom, 1e-6 * k_scale_ * inf_norm(u));
      resi_rela = denom > 0.0 ? resi_maxi / denom : resi_maxi;
      char line[96];
      std::snprintf(line, sizeof line, "  | %4d |  %14.6e |  %14.6e |", iter, resi_rela, resi_maxi);
      log_.info(line);
      if (!std::isfinite(resi_maxi))
        throw ConvergenceError("the residual became non-finite at instant " + sci(t));
      const bool rela_ok = options_.resi_glob_rela <= 0.0 || resi_rela <= options_.resi_glob_rela;
      const bool maxi_ok = options_.resi_glob_maxi <= 0.0 || resi_maxi <= options_.resi_glob_maxi;
      if (iter > 0 && rela_ok && maxi_ok) {
        converged = true;
        stats_.resi_glob_rela = resi_rela;
        break;
      }
      if (iter == options_.iter_glob_maxi) break;

      // With no contact point active, the bodies must be held by Dirichlet
      // conditions alone; the indefinite backends would not say when they are
      // not (round-off hides the zero pivot), so check the elastic part once.
      // Without contact the same holds for UMFPACK and MUMPS, which return some
      // solution of a singular but consistent system (a free rigid translation).
      if (!rigid_checked_ && (contact_ ? contact_->n_active() == 0 : options_.solver != SolverKind::Cholmod)) {
        Stopwatch watch(stats_.assemble_seconds);
        if (auto rigid = find_rigid_body_mode(model_, dofs_, cons.free_index, k_full_, t)) throw *rigid;
        rigid_checked_ = true;
      }
      const Vector du = newton_correction(t, iter, cons, k_contact, r_free);
      for (int eq = 0; eq < n; ++eq)
        if (cons.free_index[eq] >= 0) u[eq] += du[cons.free_index[eq]];
      ++total_newton;
    }
    if (!converged)
      throw ConvergenceError("Newton did not converge at instant " + sci(t) + " within ITER_GLOB_MAXI = " +
                                 std::to_string(options_.iter_glob_maxi) + " iterations",
                             {"last residuals: RESI_GLOB_RELA = " + sci(resi_rela) + ", RESI_GLOB_MAXI = " + sci(resi_maxi),
                              "loop: Newton (contact/geometry fixed-point pass " + std::to_string(fixed_point) + ")"});
    if (!contact_) break;
    log_.info("contact: " + std::to_string(contact_->n_active()) + " active point(s) in this pass");
    ++stats_.contact_passes;
    bool settled = false;
    {
      Stopwatch watch(stats_.contact_seconds);
      try {
        settled = contact_->settle(u, log_);
      } catch (ConvergenceError& err) {
        err.add_hint("at instant " + sci(t) + ", after " + std::to_string(total_newton) +
                     " Newton iteration(s); last residuals: RESI_GLOB_RELA = " + sci(resi_rela) +
                     ", RESI_GLOB_MAXI = " + sci(resi_maxi));
        throw;
      }
    }
    if (settled) break;
  }
  log_.info("  converged in " + std::to_string(total_newton) + " Newton iteration(s), " +
            std::to_string(stats_.factorisations - factorisations_before) + " factorisation(s)");
}

bool StaticSolver::needs_factorisation(int k, const std::vector<int>& free_index) const {
  if (!factors_.solver || factors_.free_index != free_index) return true;  // none valid for this system
  if (options_.elastic_matrix) return false;  // the elastic matrix never changes: factorised once per run
  // Each Newton loop starts with a new tangent: a new instant (code_aster's REAC_INCR = 1), or a
  // new contact pass, whose statuses or pairing changed the contact terms of the matrix (old
  // factors do not survive an active-set change: SSNP121 A, C and the discrete deck then fail to
  // converge). code_aster goes further and rebuilds at every iteration when contact terms are
  // in the global matrix; here REAC_ITER applies within a loop.
  if (k == 0) return true;
  return options_.reac_iter > 0 && k % options_.reac_iter == 0;
}

SolverKind StaticSolver::backend_for(MatrixKind kind) {
  if (options_.solver != SolverKind::Cholmod || kind == MatrixKind::SymmetricPositiveDefinite) return options_.solver;
  // Contact with multipliers gives a symmetric indefinite system: MUMPS (LDLT with
  // pivoting) beat UMFPACK (LU) on it: SSNP121 A refined 16 times, 3.2 s vs 3.6 s and
  // 376 MB vs 608 MB. The penalised continuous method is not symmetric: MUMPS too.
  if (!backend_note_logged_)
    log_.info(std::string("CHOLMOD cannot factorise ") +
              (kind == MatrixKind::SymmetricIndefinite ? "an indefinite" : "a non-symmetric") +
              " system; using MUMPS");
  backend_note_logged_ = true;
  return SolverKind::Mumps;
}

Vector StaticSolver::newton_correction(double t, int k, const Constraints& cons, const std::vector<Triplet>& k_contact,
                                       const Vector& r_free) {
  const int n = dofs_.n_dofs();
  if (needs_factorisation(k, cons.free_index)) {
    const MatrixKind kind = contact_ && !options_.elastic_matrix ? contact_->matrix_kind()
                                                                  : MatrixKind::SymmetricPositiveDefinite;
    {
      Stopwatch watch(stats_.assemble_seconds);
      // Dirichlet by elimination: restrict to the free equations in one pass.
      if (k_contact.empty() || options_.elastic_matrix) {
        factors_.matrix = restrict_matrix(k_full_, cons.free_index, cons.n_free);
      } else {
        SparseMatrix k_c(n, n);
        k_c.setFromTriplets(k_contact.begin(), k_contact.end());
        factors_.matrix = restrict_matrix(k_full_ + k_c, cons.free_index, cons.n_free);
      }
    }
    // One solver object per instant, as before: MUMPS keeps its analysis while the pattern holds.
    if (!factors_.solver) factors_.solver = make_linear_solver(backend_for(kind));
    factors_.free_index = cons.free_index;
    factors_.iteration = k;
    try {
      Stopwatch watch(stats_.factorize_seconds);
      factors_.solver->factorize(factors_.matrix, kind);
    } catch (const SolveError& err) {
      factors_ = Factorisation{};
      if (err.out_of_memory()) throw;
      throw diagnose_singular_system(model_, dofs_, cons.free_index, k_full_, err, t);
    }
    ++stats_.factorisations;
  } else {
    log_.info(options_.elastic_matrix
                  ? std::string("         (factorisation of the elastic matrix reused)")
                  : "         (factorisation of iteration " + std::to_string(factors_.iteration) + " reused)");
  }
  // Refinement against the factorised matrix: with reused factors this is a modified
  // Newton step K_old du = -r, not a solve of the current tangent.
  Vector du;
  RefinedSolve accuracy;
  {
    Stopwatch watch(stats_.solve_seconds);
    accuracy = solve_with_refinement(*factors_.solver, factors_.matrix, -r_free, du);
  }
  ++stats_.newton_iterations;
  stats_.refinement_steps += accuracy.steps;
  // A direct solver may return a "solution" of a singular system without flagging it
  // (MUMPS misses null pivots that are round-off rather than exact zeros): check the
  // solve itself, and locate the rigid-body mode when it did not solve the system.
  const double raw_error = accuracy.raw_residual, solve_error = accuracy.residual;
  stats_.solve_residual_raw = std::max(stats_.solve_residual_raw, raw_error);
  stats_.solve_residual = std::max(stats_.solve_residual, solve_error);
  if (!(solve_error <= kSolveTolerance))
    throw diagnose_singular_system(
        model_, dofs_, cons.free_index, k_full_,
        SolveError("the linear solver returned no accurate solution (relative residual of the solve " +
                   sci(raw_error) + ", " + sci(solve_error) + " after iterative refinement; accepted below " +
                   sci(kSolveTolerance) + ")"),
        t);
  return du;
}

}  // namespace lunaster::engine
