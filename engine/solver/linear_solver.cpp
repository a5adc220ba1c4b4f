/// Backend factory.
#include "engine/solver/linear_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/error.hpp"
#include "engine/core/two_workers.hpp"
#include "engine/solver/backends.hpp"
#include "engine/solver/blas.hpp"

namespace lunaster::engine {

std::string ordering_name(FactorOrdering ordering) {
  switch (ordering) {
    case FactorOrdering::Auto: return "the backend's choice";
    case FactorOrdering::Metis: return "METIS (nested dissection of the node graph)";
    case FactorOrdering::Amd: return "AMD (approximate minimum degree)";
    case FactorOrdering::Amf: return "AMF (approximate minimum fill)";
    case FactorOrdering::Qamd: return "QAMD";
    case FactorOrdering::Pord: return "PORD";
    case FactorOrdering::Rcm: return "reverse Cuthill-McKee";
    case FactorOrdering::Natural: return "natural (the equations' own order)";
  }
  return "?";
}

std::unique_ptr<LinearSolver> make_linear_solver(SolverKind kind, const IterativeSettings& iterative) {
  configure_blas();
  switch (kind) {
    case SolverKind::Cholmod: return make_cholmod_solver();
    case SolverKind::Umfpack: return make_umfpack_solver();
    case SolverKind::Mumps: return make_mumps_solver();
    case SolverKind::Petsc: return make_petsc_solver(iterative);
  }
  throw InternalError("make_linear_solver: unknown solver kind");
}

namespace {

class IterativeWithFallback final : public LinearSolver {
 public:
  IterativeWithFallback(const IterativeSettings& settings, SolverKind direct,
                        std::function<void(const std::string&)> note)
      : iterative_(make_linear_solver(SolverKind::Petsc, settings)), direct_kind_(direct), note_(std::move(note)) {}

  void factorize(const SparseMatrix& a, MatrixKind kind) override {
    a_ = &a, kind_ = kind;
    if (!fallen_) {
      try {
        iterative_->factorize(a, kind);
        return;
      } catch (const SolveError& err) {
        if (err.out_of_memory()) throw;
        fall_back(err.message());
      }
    }
    direct_->factorize(a, kind);
  }
  Vector solve(const Vector& b) const override {
    if (!fallen_) {
      try {
        return iterative_->solve(b);
      } catch (const SolveError& err) {
        if (err.failure().what != Failure::What::IterativeSolve || !a_) throw;
        fall_back(err.message());
        direct_->factorize(*a_, kind_);
      }
    }
    return direct_->solve(b);
  }
  std::string name() const override {
    return fallen_ ? direct_->name() + " (after " + iterative_->name() + ")" : iterative_->name();
  }
  int failed_column() const override { return fallen_ ? direct_->failed_column() : -1; }
  bool iterative() const override { return !fallen_; }
  void set_layout(SystemLayout layout) override {
    if (!fallen_) iterative_->set_layout(std::move(layout));
  }
  bool multiply(const Vector& x, Vector& y) const override { return !fallen_ && iterative_->multiply(x, y); }
  int iterations() const override { return fallen_ ? 0 : iterative_->iterations(); }
  void configure(const FactorSettings& settings) override {  // the factorisation's singularity test, if it comes
    test_ = settings.singularity;
  }
  int singular_column() const override { return fallen_ ? direct_->singular_column() : -1; }
  std::string singular_note() const override { return fallen_ ? direct_->singular_note() : std::string(); }

 private:
  void fall_back(const std::string& why) const {
    fallen_ = true;
    direct_ = make_linear_solver(direct_kind_);
    FactorSettings settings;
    settings.singularity = test_;
    direct_->configure(settings);
    if (note_)
      note_("  solver chosen automatically: " + iterative_->name() + " failed (" + why + "); " + direct_->name() +
            " factorises the system from now on");
  }

  std::unique_ptr<LinearSolver> iterative_;
  SolverKind direct_kind_;
  std::function<void(const std::string&)> note_;
  // solve() is const for its callers; a failed iterative solve changes backend there.
  mutable std::unique_ptr<LinearSolver> direct_;
  mutable bool fallen_ = false;
  const SparseMatrix* a_ = nullptr;
  MatrixKind kind_ = MatrixKind::SymmetricPositiveDefinite;
  SingularityTest test_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_iterative_with_fallback(const IterativeSettings& iterative, SolverKind direct,
                                                           std::function<void(const std::string&)> note) {
  return std::make_unique<IterativeWithFallback>(iterative, direct, std::move(note));
}

double SingularityTest::pivot_ratio() const { return digits < 0 ? 0.0 : std::pow(10.0, -digits); }

double relative_residual(const SparseMatrix& a, const Vector& x, const Vector& b) {
  return relative_residual([&a](const Vector& v) -> Vector { return a * v; }, x, b);
}

double relative_residual(const MatrixProduct& a, const Vector& x, const Vector& b, const VectorNorm* norm) {
  if (!norm) {
    if (!x.allFinite()) return std::numeric_limits<double>::infinity();
    return (a(x) - b).norm() / std::max(b.norm(), std::numeric_limits<double>::min());
  }
  const double relative = (*norm)(Vector(a(x) - b)) / std::max((*norm)(b), std::numeric_limits<double>::min());
  return std::isfinite(relative) ? relative : std::numeric_limits<double>::infinity();
}

RefinedSolve solve_with_refinement(const LinearSolver& solver, const SparseMatrix& a, const Vector& b, Vector& x,
                                   int max_steps, double refine_above) {
  return solve_with_refinement(solver, [&a](const Vector& v) -> Vector { return a * v; }, b, x, max_steps,
                               refine_above);
}

void add_abs_product(const SparseMatrix& a, const Vector& x, Vector& y) {
  for (int j = 0; j < a.outerSize(); ++j) {
    const double xj = std::abs(x[j]);
    if (xj == 0.0) continue;
    for (SparseMatrix::InnerIterator it(a, j); it; ++it) y[it.row()] += std::abs(it.value()) * xj;
  }
}

Vector symmetric_times(const SparseMatrix& a, const Vector& x) {
  LUNASTER_ASSERT(a.isCompressed() && a.rows() == a.cols() && a.cols() == x.size(), "symmetric_times: shapes");
  const int n = static_cast<int>(a.cols());
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* values = a.valuePtr();
  Vector y(n);
  auto columns = [&](int begin, int end) {
    for (int j = begin; j < end; ++j) {
      double sum = 0.0;
      for (int p = outer[j]; p < outer[j + 1]; ++p) sum += values[p] * x[inner[p]];
      y[j] = sum;
    }
  };
  if (a.nonZeros() < 200000) {
    columns(0, n);
    return y;
  }
  // Split where half the entries are: the first column whose start passes the middle.
  const int middle = static_cast<int>(std::upper_bound(outer, outer + n, outer[n] / 2) - outer) - 1;
  run_two_workers([&](int w, size_t&) { w == 0 ? columns(0, middle) : columns(middle, n); });
  return y;
}

RefinedSolve solve_with_refinement(const LinearSolver& solver, const MatrixProduct& a, const Vector& b, Vector& x,
                                   int max_steps, double refine_above, const MatrixProduct* abs_product,
                                   double accept, const VectorNorm* norm, bool fixed_steps) {
  // One product A x per iterate: its residual serves the relative residual, the backward
  // error and the next step.
  const auto size = [norm](const Vector& v) { return norm ? (*norm)(v) : v.norm(); };
  const double b_norm = std::max(size(b), std::numeric_limits<double>::min());
  auto residual_of = [&](const Vector& v, Vector& r) {
    if (!norm && !v.allFinite()) return std::numeric_limits<double>::infinity();
    r = a(v) - b;
    const double relative = size(r) / b_norm;
    return std::isfinite(relative) ? relative : std::numeric_limits<double>::infinity();
  };
  RefinedSolve out;
  x = solver.solve(b);
  Vector r;
  out.raw_residual = out.residual = residual_of(x, r);
  auto backward_stable = [&] {
    if (!abs_product || !std::isfinite(out.residual) || out.residual > accept) return false;
    // Row by row: a row whose terms are small (a multiplier's, beside penalty-sized
    // stiffness rows) must meet its own round-off, not the largest row's.
    const Vector scale = (*abs_product)(x) + b.cwiseAbs();
    for (Eigen::Index i = 0; i < r.size(); ++i)
      if (std::abs(r[i]) > kBackwardStable * scale[i]) return false;
    return true;
  };
  if (fixed_steps) {
    // Every step from the last iterate, the best one kept (and its residual).
    Vector last = x, r_last = r;
    for (; out.steps < max_steps && last.allFinite(); ++out.steps) {
      last -= solver.solve(r_last);
      const double next = residual_of(last, r_last);
      if (next < out.residual) {
        x = last;
        r = r_last;
        out.residual = next;
      }
    }
  }
  while (!fixed_steps && out.steps < max_steps && std::isfinite(out.residual) && out.residual > refine_above &&
         !backward_stable()) {
    Vector refined = x - solver.solve(r);
    ++out.steps;
    Vector r_refined;
    const double next = residual_of(refined, r_refined);
    if (!(next < out.residual)) break;  // no gain: the factorisation is as good as it gets
    x = std::move(refined);
    r = std::move(r_refined);
    out.residual = next;
  }
  out.ax_minus_b = std::move(r);
  return out;
}

}  // namespace lunaster::engine
