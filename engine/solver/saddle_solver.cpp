/// Symmetric saddle-point systems on CHOLMOD (see saddle_solver.hpp).
#include "engine/solver/saddle_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/SparseCholesky>

#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"
#include "engine/solver/krylov.hpp"

namespace lunaster::engine {
namespace {

/// D's share of each constraint row's scale: small enough that the preconditioner is the
/// system to about 1e-6, large enough that S stays well within CHOLMOD's reach (the SSNP121
/// 3D contact benchmark: relative residual 1.5e-9 after one preconditioned step, 9e-15 after
/// two; 1e-9 gave 1.5e-6 after one, S then being too ill-conditioned).
constexpr double kDelta = 1e-6;
constexpr int kGmresIterations = 30;
constexpr int kGmresCycles = 3;
/// What a direct solve gives: |A x - b| <= 1e-13 |b|, or, where b is small beside A x, a
/// backward error of 1e-14 row by row, |A x - b|_i <= 1e-14 (|A| |x| + |b|)_i: the driver's
/// own test, so that it does not refine again. (Normwise, with |A|_inf |x|_inf, the multiplier
/// rows, far smaller than the penalty-sized ones, were accepted at a relative residual of
/// 1e-5 and refined by the driver.)
constexpr double kRelativeResidual = 1e-13;
constexpr double kBackwardError = 1e-14;
/// GMRES failures (on different factorisations) after which the direct backend stays.
constexpr int kFailuresToGiveUp = 2;

/// The system split into displacements (u) and multipliers (l), and the preconditioner:
/// u from S's factorisation (the multipliers eliminated with D), then the multipliers from
/// their own rows with C whole.
class Split final : public LinearSolver {
 public:
  std::vector<int> u_eqs, l_eqs;
  SparseMatrix b;          ///< n_l x n_u, column-major: the constraint rows
  Vector d_inv;            ///< 1 / D
  Eigen::SimplicialLDLT<SparseMatrix> multipliers;  ///< E - C, SPD (E: kDelta times each row's scale)
  std::unique_ptr<LinearSolver> schur = make_linear_solver(SolverKind::Cholmod);

  void factorize(const SparseMatrix&, MatrixKind) override {
    throw InternalError("the saddle-point preconditioner is built by its owner");
  }
  Vector solve(const Vector& r) const override {
    const Eigen::Index nu = static_cast<Eigen::Index>(u_eqs.size()), nl = static_cast<Eigen::Index>(l_eqs.size());
    Vector ru(nu), rl(nl);
    for (Eigen::Index i = 0; i < nu; ++i) ru[i] = r[u_eqs[i]];
    for (Eigen::Index i = 0; i < nl; ++i) rl[i] = r[l_eqs[i]];
    const Vector xu = schur->solve(ru + b.transpose() * d_inv.cwiseProduct(rl));
    // The multipliers from their own rows, B xu + (C - E) xl = rl, with C whole: exact for
    // the multipliers without a constraint row (an inactive point's, whose C is a mass).
    const Vector xl = -multipliers.solve(rl - b * xu);
    Vector x(r.size());
    for (Eigen::Index i = 0; i < nu; ++i) x[u_eqs[i]] = xu[i];
    for (Eigen::Index i = 0; i < nl; ++i) x[l_eqs[i]] = xl[i];
    return x;
  }
  std::string name() const override { return "CHOLMOD (the multipliers' Schur complement)"; }
};

/// max_i |r_i| / (|A| |x| + |b|)_i; infinite when a
/// row with nothing on the right has a residual.
double row_backward_error(const SparseMatrix& a, const Vector& x, const Vector& b, const Vector& r) {
  Vector scale = b.cwiseAbs();
  add_abs_product(a, x, scale);
  double worst = 0.0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    if (r[i] == 0.0) continue;
    worst = std::max(worst, scale[i] > 0.0 ? std::abs(r[i]) / scale[i] : INFINITY);
  }
  return worst;
}

class SaddleSolver final : public LinearSolver {
 public:
  SaddleSolver(SolverKind direct, std::function<void(const std::string&)> note)
      : direct_kind_(direct), note_(std::move(note)) {}

  void factorize(const SparseMatrix& a, MatrixKind kind) override {
    a_ = &a, kind_ = kind, split_ = false, iterations_ = 0;
    if (!fallen_ && kind == MatrixKind::SymmetricIndefinite && build(a)) {
      try {
        // A 3D-like S (over 40 entries a column) of over 1e4 equations goes straight to
        // nested dissection, which CHOLMOD's AUTO would only choose after an AMD analysis:
        // on the SSNP121 3D contact benchmark METIS needs 1.13e10 operations, AMD 2.72e10.
        const double per_column = static_cast<double>(schur_.nonZeros()) / std::max<double>(1.0, schur_.cols());
        const bool nested = settings_.ordering == FactorOrdering::Auto && per_column > 40.0 && schur_.cols() > 10000;
        FactorSettings schur_settings = settings_;
        if (nested) schur_settings.ordering = FactorOrdering::Metis;
        split_data_->schur->configure(schur_settings);
        split_data_->schur->factorize(schur_, MatrixKind::SymmetricPositiveDefinite);
        split_ = true;
        return;
      } catch (const SolveError& err) {
        if (err.out_of_memory()) throw;
        give_up("its Schur complement is not positive definite (" + err.message() + ")");
      }
    }
    direct().factorize(a, kind);
  }

  Vector solve(const Vector& b) const override {
    if (!split_) return direct().solve(b);
    // GMRES, restarted on its true residual: its own estimate runs ahead of the true
    // residual when the preconditioner's solves carry S's round-off (S is conditioned by
    // 1 / kDelta), so each cycle starts again from b - A x.
    Vector x = Vector::Zero(b.size()), r = b;
    const double b_norm = b.norm();
    double residual = 1.0, backward = 1.0;
    iterations_ = 0;
    for (int cycle = 0; cycle < kGmresCycles; ++cycle) {
      Vector dx;
      const KrylovResult k = preconditioned_gmres(*a_, *split_data_, r, dx, kGmresIterations, kRelativeResidual);
      iterations_ += k.iterations;
      x += dx;
      r = b - (*a_) * x;
      residual = b_norm > 0.0 ? r.norm() / b_norm : r.norm();
      backward = row_backward_error(*a_, x, b, r);
      if (!std::isfinite(residual)) break;
      if (residual <= kRelativeResidual || backward <= kBackwardError) return x;
    }
    // Not a direct solve's accuracy: the direct backend factorises this matrix and solves.
    if (++failures_ >= kFailuresToGiveUp)
      give_up("GMRES left a relative residual of " + std::to_string(residual) + " after " +
              std::to_string(iterations_) + " iterations");
    split_ = false;
    direct().factorize(*a_, kind_);
    return direct().solve(b);
  }

  std::string name() const override {
    if (split_) return split_data_->name() + " with GMRES";
    if (direct_) return direct_->name();
    return direct_kind_ == SolverKind::Umfpack ? "UMFPACK" : direct_kind_ == SolverKind::Mumps ? "MUMPS" : "CHOLMOD";
  }
  int failed_column() const override { return direct_ && !split_ ? direct_->failed_column() : -1; }
  int iterations() const override { return split_ ? iterations_ : 0; }
  void configure(const FactorSettings& settings) override {
    settings_ = settings;
    split_data_->schur->configure(settings);
    if (direct_) direct_->configure(settings);
  }
  std::string approximation_note() const override {
    return split_ || !direct_ ? std::string() : direct_->approximation_note();
  }
  int singular_column() const override {
    if (!split_) return direct_ ? direct_->singular_column() : -1;
    const int c = split_data_->schur->singular_column();  // S's own numbering: the displacements'
    return c >= 0 && c < static_cast<int>(split_data_->u_eqs.size()) ? split_data_->u_eqs[c] : -1;
  }
  std::string singular_note() const override {
    return split_ ? split_data_->schur->singular_note() : direct_ ? direct_->singular_note() : std::string();
  }
  void set_layout(SystemLayout layout) override {  // the direct backend's (S has no use for it)
    if (direct_) direct_->set_layout(std::move(layout));
    else layout_ = std::move(layout), has_layout_ = true;
  }
  std::string memory_used() const override { return split_ || !direct_ ? std::string() : direct_->memory_used(); }
  std::string ordering_used() const override {
    return split_ ? split_data_->schur->ordering_used() : direct_ ? direct_->ordering_used() : std::string();
  }
  std::string analysis_note() const override {
    return split_ ? split_data_->schur->analysis_note() : direct_ ? direct_->analysis_note() : std::string();
  }

 private:
  LinearSolver& direct() const {
    if (!direct_) {
      direct_ = make_linear_solver(direct_kind_);
      direct_->configure(settings_);
      if (has_layout_) direct_->set_layout(std::move(layout_)), has_layout_ = false;
    }
    return *direct_;
  }

  void give_up(const std::string& why) const {
    if (fallen_) return;
    fallen_ = true;
    if (note_) note_("  the multipliers' Schur complement on CHOLMOD gave way: " + why + "; " + direct().name() +
                     " factorises the system from now on");
  }

  /// Splits `a` into its displacement and multiplier equations and builds S; false when
  /// the system is not a saddle point this backend takes (no multipliers, or too many).
  bool build(const SparseMatrix& a) {
    const Eigen::Index n = a.rows();
    Split& s = *split_data_;
    std::vector<int> place(static_cast<size_t>(n), -1);  // index in u (>= 0) or -1 - index in l
    const Vector diag = a.diagonal();
    s.u_eqs.clear(), s.l_eqs.clear();
    for (Eigen::Index i = 0; i < n; ++i) {
      if (diag[i] > 0.0) place[i] = static_cast<int>(s.u_eqs.size()), s.u_eqs.push_back(static_cast<int>(i));
      else place[i] = -1 - static_cast<int>(s.l_eqs.size()), s.l_eqs.push_back(static_cast<int>(i));
    }
    const int nu = static_cast<int>(s.u_eqs.size()), nl = static_cast<int>(s.l_eqs.size());
    if (nl == 0 || 4 * static_cast<Eigen::Index>(nl) > n) return false;
    // B (n_l x n_u) column by column: the multiplier rows of the displacement columns (rows
    // come sorted, and place[] keeps their order). Stored entries stay, zeros included, so
    // that S's pattern follows a's alone (CHOLMOD keeps its analysis while it does not change).
    std::vector<int> b_outer(static_cast<size_t>(nu) + 1, 0), b_inner;
    std::vector<double> b_values;
    std::vector<double> scale(static_cast<size_t>(nl), 0.0);
    for (int ju = 0; ju < nu; ++ju) {
      const int j = s.u_eqs[ju];
      for (SparseMatrix::InnerIterator it(a, j); it; ++it) {
        const int p = place[it.row()];
        if (p >= 0) continue;
        const int il = -1 - p;
        b_inner.push_back(il), b_values.push_back(it.value());
        scale[il] += it.value() * it.value() / diag[j];
      }
      b_outer[ju + 1] = static_cast<int>(b_inner.size());
    }
    // E - C: the multipliers' block negated, plus kDelta times each row's scale.
    std::vector<Triplet> e_minus_c;
    for (int il = 0; il < nl; ++il) {
      e_minus_c.emplace_back(il, il, kDelta * scale[il]);
      for (SparseMatrix::InnerIterator it(a, s.l_eqs[il]); it; ++it)
        if (place[it.row()] < 0) e_minus_c.emplace_back(-1 - place[it.row()], il, -it.value());
    }
    s.b = Eigen::Map<const SparseMatrix>(nl, nu, static_cast<Eigen::Index>(b_inner.size()), b_outer.data(),
                                         b_inner.data(), b_values.data());
    {
      SparseMatrix m(nl, nl);
      m.setFromTriplets(e_minus_c.begin(), e_minus_c.end());
      for (int il = 0; il < nl; ++il)  // an empty multiplier row: the system is singular there anyway
        if (m.coeff(il, il) <= 0.0) m.coeffRef(il, il) = 1.0;
      // D is E - C's diagonal (C's diagonal is <= 0 on the multipliers): m's own diagonal.
      s.d_inv = m.diagonal().cwiseInverse();
      s.multipliers.compute(m);
      if (s.multipliers.info() != Eigen::Success) return false;
    }
    // S = A + B^T D^-1 B. A column that no multiplier row touches is A's own column (the u
    // rows of a's column, in order). The others (the contact surfaces' equations) gather
    // A's column and, for each multiplier row i of B's column j, B_ij / d_i times row i of B,
    // in a dense accumulator; their rows are sorted and kept until S is written.
    const SparseMatrix bt = s.b.transpose();  // B's rows, one column each
    std::vector<double> acc(static_cast<size_t>(nu), 0.0);
    std::vector<char> seen(static_cast<size_t>(nu), 0);
    std::vector<std::vector<std::pair<int, double>>> coupled(static_cast<size_t>(nu));
    std::vector<int> rows;
    for (int ju = 0; ju < nu; ++ju) {
      if (b_outer[ju] == b_outer[ju + 1]) continue;
      rows.clear();
      auto touch = [&](int r, double v) {
        if (!seen[r]) seen[r] = 1, rows.push_back(r);
        acc[r] += v;
      };
      for (SparseMatrix::InnerIterator it(a, s.u_eqs[ju]); it; ++it)
        if (place[it.row()] >= 0) touch(place[it.row()], it.value());
      for (SparseMatrix::InnerIterator ib(s.b, ju); ib; ++ib) {
        const double f = ib.value() * s.d_inv[ib.row()];
        for (SparseMatrix::InnerIterator ir(bt, ib.row()); ir; ++ir) touch(static_cast<int>(ir.row()), f * ir.value());
      }
      std::sort(rows.begin(), rows.end());
      auto& column = coupled[ju];
      column.reserve(rows.size());
      for (int r : rows) column.emplace_back(r, acc[r]), acc[r] = 0.0, seen[r] = 0;
    }
    schur_.resize(nu, nu);
    schur_.setZero();
    int* outer = schur_.outerIndexPtr();
    outer[0] = 0;
    for (int ju = 0; ju < nu; ++ju) {
      int count = 0;
      if (!coupled[ju].empty()) count = static_cast<int>(coupled[ju].size());
      else
        for (SparseMatrix::InnerIterator it(a, s.u_eqs[ju]); it; ++it) count += place[it.row()] >= 0;
      outer[ju + 1] = outer[ju] + count;
    }
    schur_.resizeNonZeros(outer[nu]);
    // Written once per factorisation: on huge pages, one fault per 2 MB (engine/core/memory.hpp).
    advise_huge_pages(schur_.innerIndexPtr(), sizeof(int) * static_cast<std::size_t>(outer[nu]));
    advise_huge_pages(schur_.valuePtr(), sizeof(double) * static_cast<std::size_t>(outer[nu]));
    int* inner = schur_.innerIndexPtr();
    double* values = schur_.valuePtr();
    for (int ju = 0; ju < nu; ++ju) {
      int at = outer[ju];
      if (!coupled[ju].empty()) {
        for (const auto& [r, v] : coupled[ju]) inner[at] = r, values[at++] = v;
        continue;
      }
      for (SparseMatrix::InnerIterator it(a, s.u_eqs[ju]); it; ++it)
        if (place[it.row()] >= 0) inner[at] = place[it.row()], values[at++] = it.value();
    }
    return true;
  }

  SolverKind direct_kind_;
  std::function<void(const std::string&)> note_;
  FactorSettings settings_;  ///< the direct backend's; S's CHOLMOD reads the ordering and the singularity test
  mutable SystemLayout layout_;  ///< given before the direct backend existed
  mutable bool has_layout_ = false;
  std::unique_ptr<Split> split_data_ = std::make_unique<Split>();
  SparseMatrix schur_;
  const SparseMatrix* a_ = nullptr;  ///< the matrix last factorised: alive until the next factorize()
  MatrixKind kind_ = MatrixKind::SymmetricIndefinite;
  // solve() is const for its callers; a failed GMRES hands the system to the direct backend.
  mutable std::unique_ptr<LinearSolver> direct_;
  mutable bool split_ = false;  ///< this factorisation is S's (else the direct backend's)
  mutable bool fallen_ = false;
  mutable int failures_ = 0;
  mutable int iterations_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_saddle_solver(SolverKind direct, std::function<void(const std::string&)> note) {
  return std::make_unique<SaddleSolver>(direct, std::move(note));
}

}  // namespace lunaster::engine
