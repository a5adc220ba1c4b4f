/// UMFPACK multifrontal LU. Keeps a copy of the matrix (umfpack_di_solve needs
/// it for iterative refinement), and its symbolic analysis while the pattern and
/// the strategy stay the same (the Newton and contact loops refactorise one pattern). On a singular matrix the failed column is
/// read cheaply from the diagonal of U and the column permutation Q.
#include <umfpack.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/solver/backends.hpp"

namespace lunaster::engine {
namespace {

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver() { umfpack_di_defaults(control_); }
  ~UmfpackSolver() override { release(); }
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  void factorize(const SparseMatrix& a, MatrixKind kind) override;
  Vector solve(const Vector& b) const override;
  std::string name() const override { return "UMFPACK"; }
  int failed_column() const override { return failed_; }
  void configure(const FactorSettings& settings) override {  // the ordering alone
    const FactorOrdering ordering = settings.ordering;
    LUNASTER_ASSERT(any_backend_orders_by(ordering), "UMFPACK orders by AMD, METIS, reverse Cuthill-McKee or not at all");
    ordering_ = ordering;
    release();  // analyse again
    control_[UMFPACK_ORDERING] = ordering == FactorOrdering::Metis     ? UMFPACK_ORDERING_METIS
                                 : ordering == FactorOrdering::Natural ? UMFPACK_ORDERING_NONE
                                 : ordering == FactorOrdering::Rcm     ? UMFPACK_ORDERING_GIVEN
                                                                       : UMFPACK_DEFAULT_ORDERING;
  }
  std::string ordering_used() const override;

 private:
  void release() {
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  }
  bool same_pattern(const SparseMatrix& a) const {
    return symbolic_ && a.rows() == a_.rows() && a.nonZeros() == a_.nonZeros() &&
           std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.cols() + 1, a_.outerIndexPtr()) &&
           std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), a_.innerIndexPtr());
  }
  int zero_pivot_column() const;

  double control_[UMFPACK_CONTROL];
  mutable double info_[UMFPACK_INFO];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  SparseMatrix a_;
  FactorOrdering ordering_ = FactorOrdering::Auto;
  int ordering_used_ = -1;  ///< Info[UMFPACK_ORDERING_USED] of the last symbolic analysis
  int failed_ = -1;
};

std::string UmfpackSolver::ordering_used() const {
  if (!symbolic_) return {};
  switch (ordering_used_) {
    case UMFPACK_ORDERING_AMD: return "AMD or COLAMD";
    case UMFPACK_ORDERING_METIS: return "METIS (UMFPACK's, on the graph of the equations)";
    case UMFPACK_ORDERING_NONE: return ordering_name(FactorOrdering::Natural);
    case UMFPACK_ORDERING_GIVEN: return ordering_name(ordering_) + ", given";
    default: return "UMFPACK ordering " + std::to_string(ordering_used_);
  }
}

/// Column (original numbering) of the smallest |U_kk|, if it is negligible.
int UmfpackSolver::zero_pivot_column() const {
  const int n = static_cast<int>(a_.cols());
  std::vector<int> p(n), q(n);
  std::vector<double> dx(n), rs(n);
  int do_recip = 0;
  if (umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, p.data(), q.data(), dx.data(),
                             &do_recip, rs.data(), numeric_) != UMFPACK_OK)
    return -1;
  double largest = 0.0;
  for (double d : dx) largest = std::max(largest, std::abs(d));
  int worst = -1;
  for (int k = 0; k < n; ++k)
    if (std::abs(dx[k]) <= 1e-14 * largest && (worst < 0 || std::abs(dx[k]) < std::abs(dx[worst]))) worst = k;
  return worst < 0 ? -1 : q[worst];
}

void UmfpackSolver::factorize(const SparseMatrix& a, MatrixKind kind) {
  failed_ = -1;
  LUNASTER_ASSERT(a.rows() == a.cols(), "UMFPACK: matrix is not square");
  const double strategy = kind == MatrixKind::General ? UMFPACK_STRATEGY_AUTO : UMFPACK_STRATEGY_SYMMETRIC;
  SparseMatrix compressed = a;
  compressed.makeCompressed();
  const bool keep_symbolic = same_pattern(compressed) && control_[UMFPACK_STRATEGY] == strategy;
  if (numeric_) umfpack_di_free_numeric(&numeric_);
  if (!keep_symbolic) release();
  a_ = std::move(compressed);
  control_[UMFPACK_STRATEGY] = strategy;
  const int n = static_cast<int>(a_.rows());
  int status = UMFPACK_OK;
  if (!keep_symbolic) {
    if (ordering_ == FactorOrdering::Rcm) {
      // Reverse Cuthill-McKee of the node graph, given as the column pre-ordering.
      std::vector<int> q = given_ordering(a_, ordering_);
      if (q.empty()) throw SolveError("UMFPACK: the " + ordering_name(ordering_) + " ordering failed");
      status = umfpack_di_qsymbolic(n, n, a_.outerIndexPtr(), a_.innerIndexPtr(), a_.valuePtr(), q.data(), &symbolic_,
                                    control_, info_);
    } else {
      status = umfpack_di_symbolic(n, n, a_.outerIndexPtr(), a_.innerIndexPtr(), a_.valuePtr(), &symbolic_, control_,
                                   info_);
    }
    ordering_used_ = static_cast<int>(info_[UMFPACK_ORDERING_USED]);
    if (status == UMFPACK_ERROR_out_of_memory)
      throw SolveError::out_of_memory("UMFPACK", n, "symbolic analysis, status -1");
    if (status != UMFPACK_OK) throw SolveError("UMFPACK: symbolic analysis failed (status " + std::to_string(status) + ")");
  }
  status = umfpack_di_numeric(a_.outerIndexPtr(), a_.innerIndexPtr(), a_.valuePtr(), symbolic_, &numeric_, control_,
                              info_);
  if (status == UMFPACK_WARNING_singular_matrix) {
    failed_ = zero_pivot_column();
    const std::string where = failed_ >= 0 ? " at equation " + std::to_string(failed_) : std::string();
    release();
    throw SolveError("UMFPACK: singular matrix" + where,
                     {"check the boundary conditions (rigid-body modes) and the contact definition"});
  }
  if (status == UMFPACK_ERROR_out_of_memory) {
    release();
    throw SolveError::out_of_memory("UMFPACK", n, "numeric factorisation, status -1");
  }
  if (status != UMFPACK_OK) {
    release();
    throw SolveError("UMFPACK: numeric factorisation failed (status " + std::to_string(status) + ")");
  }
}

Vector UmfpackSolver::solve(const Vector& b) const {
  if (!numeric_) throw InternalError("UMFPACK: solve called without a valid factorisation");
  Vector x(b.size());
  const int status = umfpack_di_solve(UMFPACK_A, a_.outerIndexPtr(), a_.innerIndexPtr(), a_.valuePtr(), x.data(),
                                      b.data(), numeric_, control_, info_);
  if (status != UMFPACK_OK) throw SolveError("UMFPACK: solve failed (status " + std::to_string(status) + ")");
  return x;
}

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

}  // namespace lunaster::engine
