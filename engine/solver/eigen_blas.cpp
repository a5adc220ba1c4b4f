/// The dense kernels CHOLMOD's supernodal factorisation and solve call (dgemm,
/// dsyrk, dtrsm, dpotrf, dgemv, dtrsv; MUMPS uses the first three as well),
/// implemented with Eigen. Defined in the executable, they take precedence
/// over the system BLAS when the dynamic linker binds libcholmod/libdmumps
/// (symbol interposition): Debian's default BLAS is the unoptimised reference
/// implementation, several times slower than Eigen's blocked kernels. Large
/// GEMM/TRSM calls are split over two threads (the target machine has 2 cores).
/// Fortran calling convention: every argument by pointer; hidden string
/// lengths at the end are ignored.
#include <algorithm>
#include <thread>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace {

using Eigen::Dynamic;
using Eigen::OuterStride;
using Mat = Eigen::Map<Eigen::Matrix<double, Dynamic, Dynamic>, 0, OuterStride<>>;
using CMat = Eigen::Map<const Eigen::Matrix<double, Dynamic, Dynamic>, 0, OuterStride<>>;
using Vec = Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<>>;
using CVec = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>;

bool is(const char* c, char v) { return (*c | 0x20) == (v | 0x20); }

/// Runs f(begin, end) on [0, n) split in two halves when the work is large.
template <class F>
void split2(int n, double flops, F&& f) {
  if (flops < 4e6 || n < 16) {
    f(0, n);
    return;
  }
  const int half = n / 2;
  std::thread helper([&] { f(half, n); });
  f(0, half);
  helper.join();
}

template <class A, class B, class C>
void gemm_block(bool ta, bool tb, double alpha, const A& a, const B& b, C&& c) {
  if (!ta && !tb) c.noalias() += alpha * a * b;
  else if (ta && !tb) c.noalias() += alpha * a.transpose() * b;
  else if (!ta && tb) c.noalias() += alpha * a * b.transpose();
  else c.noalias() += alpha * a.transpose() * b.transpose();
}

}  // namespace

extern "C" {

/// Anchor referenced by the solver backends so that this object is linked in.
int lunaster_eigen_blas_anchor() { return 1; }

void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc) {
  if (*m == 0 || *n == 0) return;
  Mat cm(c, *m, *n, OuterStride<>(*ldc));
  if (*beta == 0.0) cm.setZero();
  else if (*beta != 1.0) cm *= *beta;
  if (*k == 0 || *alpha == 0.0) return;
  const bool ta = !is(transa, 'n'), tb = !is(transb, 'n');
  const CMat am(a, ta ? *k : *m, ta ? *m : *k, OuterStride<>(*lda));
  const CMat bm(b, tb ? *n : *k, tb ? *k : *n, OuterStride<>(*ldb));
  // split the columns of C
  split2(*n, 2.0 * *m * *n * *k, [&](int j0, int j1) {
    if (j1 <= j0) return;
    auto cb = cm.middleCols(j0, j1 - j0);
    if (tb) gemm_block(ta, tb, *alpha, am, bm.middleRows(j0, j1 - j0), cb);
    else gemm_block(ta, tb, *alpha, am, bm.middleCols(j0, j1 - j0), cb);
  });
}

void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc) {
  if (*n == 0) return;
  Mat cm(c, *n, *n, OuterStride<>(*ldc));
  const bool lower = is(uplo, 'l');
  if (*beta != 1.0) {
    if (lower) {
      if (*beta == 0.0) cm.triangularView<Eigen::Lower>().setZero();
      else cm.triangularView<Eigen::Lower>() *= *beta;
    } else {
      if (*beta == 0.0) cm.triangularView<Eigen::Upper>().setZero();
      else cm.triangularView<Eigen::Upper>() *= *beta;
    }
  }
  if (*k == 0 || *alpha == 0.0) return;
  const bool t = !is(trans, 'n');
  const CMat am(a, t ? *k : *n, t ? *n : *k, OuterStride<>(*lda));
  if (lower) {
    if (t) cm.selfadjointView<Eigen::Lower>().rankUpdate(am.transpose(), *alpha);
    else cm.selfadjointView<Eigen::Lower>().rankUpdate(am, *alpha);
  } else {
    if (t) cm.selfadjointView<Eigen::Upper>().rankUpdate(am.transpose(), *alpha);
    else cm.selfadjointView<Eigen::Upper>().rankUpdate(am, *alpha);
  }
}

void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb) {
  if (*m == 0 || *n == 0) return;
  Mat bm(b, *m, *n, OuterStride<>(*ldb));
  if (*alpha != 1.0) bm *= *alpha;
  const bool left = is(side, 'l'), lower = is(uplo, 'l'), trans = !is(transa, 'n'), unit = is(diag, 'u');
  const int na = left ? *m : *n;
  const CMat am(a, na, na, OuterStride<>(*lda));
  // effective triangle of op(A): transposing swaps lower and upper
  const bool eff_lower = lower != trans;
  auto solve = [&](auto&& rhs) {
    auto run = [&](const auto& tri) {
      if (left) tri.solveInPlace(rhs);
      else tri.template solveInPlace<Eigen::OnTheRight>(rhs);
    };
    if (trans) {
      const auto at = am.transpose();
      if (eff_lower) unit ? run(at.triangularView<Eigen::UnitLower>()) : run(at.triangularView<Eigen::Lower>());
      else unit ? run(at.triangularView<Eigen::UnitUpper>()) : run(at.triangularView<Eigen::Upper>());
    } else {
      if (eff_lower) unit ? run(am.triangularView<Eigen::UnitLower>()) : run(am.triangularView<Eigen::Lower>());
      else unit ? run(am.triangularView<Eigen::UnitUpper>()) : run(am.triangularView<Eigen::Upper>());
    }
  };
  const double flops = double(na) * na * (left ? *n : *m);
  if (left) {  // columns of B are independent
    split2(*n, flops, [&](int j0, int j1) {
      if (j1 > j0) solve(bm.middleCols(j0, j1 - j0));
    });
  } else {  // rows of B are independent
    split2(*m, flops, [&](int i0, int i1) {
      if (i1 > i0) solve(bm.middleRows(i0, i1 - i0));
    });
  }
}

void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info) {
  *info = 0;
  if (*n == 0) return;
  Mat am(a, *n, *n, OuterStride<>(*lda));
  Eigen::Index failed;
  if (is(uplo, 'l')) {
    failed = Eigen::internal::llt_inplace<double, Eigen::Lower>::blocked(am);
  } else {
    auto at = am.transpose();
    failed = Eigen::internal::llt_inplace<double, Eigen::Lower>::blocked(at);
  }
  *info = failed < 0 ? 0 : static_cast<int>(failed) + 1;  // LAPACK: order of the failing leading minor
}

void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a, const int* lda,
            const double* x, const int* incx, const double* beta, double* y, const int* incy) {
  const bool t = !is(trans, 'n');
  const int lx = t ? *m : *n, ly = t ? *n : *m;
  if (ly == 0) return;
  Vec yv(y, ly, Eigen::InnerStride<>(*incy));
  if (*beta == 0.0) yv.setZero();
  else if (*beta != 1.0) yv *= *beta;
  if (lx == 0 || *alpha == 0.0) return;
  const CMat am(a, *m, *n, OuterStride<>(*lda));
  const CVec xv(x, lx, Eigen::InnerStride<>(*incx));
  if (t) yv.noalias() += *alpha * am.transpose() * xv;
  else yv.noalias() += *alpha * am * xv;
}

void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a, const int* lda,
            double* x, const int* incx) {
  if (*n == 0) return;
  const CMat am(a, *n, *n, OuterStride<>(*lda));
  Eigen::VectorXd v = Vec(x, *n, Eigen::InnerStride<>(*incx));
  const bool lower = is(uplo, 'l'), transposed = !is(trans, 'n'), unit = is(diag, 'u');
  if (!transposed) {
    if (lower) unit ? am.triangularView<Eigen::UnitLower>().solveInPlace(v) : am.triangularView<Eigen::Lower>().solveInPlace(v);
    else unit ? am.triangularView<Eigen::UnitUpper>().solveInPlace(v) : am.triangularView<Eigen::Upper>().solveInPlace(v);
  } else {
    const auto at = am.transpose();
    if (lower) unit ? at.triangularView<Eigen::UnitUpper>().solveInPlace(v) : at.triangularView<Eigen::Upper>().solveInPlace(v);
    else unit ? at.triangularView<Eigen::UnitLower>().solveInPlace(v) : at.triangularView<Eigen::Lower>().solveInPlace(v);
  }
  Vec(x, *n, Eigen::InnerStride<>(*incx)) = v;
}

}  // extern "C"
