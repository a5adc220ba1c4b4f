// The BLAS/LAPACK the solver libraries bind to (OpenBLAS, engine/solver/blas.hpp):
// which library it is, which kernels it runs, and the kernels CHOLMOD and MUMPS
// call against plain dense Eigen expressions, for every option combination,
// including sizes large enough for OpenBLAS's blocked paths.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cstdlib>
#include <string>
#include <vector>
#include <thread>

#include "engine/solver/blas.hpp"
#include "engine/solver/linear_solver.hpp"

extern "C" {
void dgemm_(const char*, const char*, const int*, const int*, const int*, const double*, const double*, const int*,
            const double*, const int*, const double*, double*, const int*);
void dsyrk_(const char*, const char*, const int*, const int*, const double*, const double*, const int*, const double*,
            double*, const int*);
void dtrsm_(const char*, const char*, const char*, const char*, const int*, const int*, const double*, const double*,
            const int*, double*, const int*);
void dpotrf_(const char*, const int*, double*, const int*, int*);
void dgemv_(const char*, const int*, const int*, const double*, const double*, const int*, const double*, const int*,
            const double*, double*, const int*);
void dtrsv_(const char*, const char*, const char*, const int*, const double*, const int*, double*, const int*);
}

namespace {

using Eigen::MatrixXd;

// Every test sets the kernels up as a run does, before its first BLAS call.
class Blas : public ::testing::Test {
 protected:
  void SetUp() override { lunaster::engine::configure_blas(); }
};

TEST_F(Blas, SolverLibrariesBindToOpenBlas) {
  // dgemm_ as the dynamic linker resolves it for every library of the process
  // (libcholmod, libdmumps and libumfpack name libblas.so.3).
  EXPECT_NE(lunaster::engine::blas_library().find("libopenblas"), std::string::npos)
      << "dgemm_ comes from " << lunaster::engine::blas_library();
}

TEST_F(Blas, KernelsMatchTheCpu) {
  // OpenBLAS's generic fallback is only right for a CPU without AVX2.
  if (std::getenv("OPENBLAS_CORETYPE")) GTEST_SKIP() << "kernels named by the environment";
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
    EXPECT_NE(lunaster::engine::blas_core(), "Prescott");
  }
}

TEST_F(Blas, ThreadCountIsSetOnce) {
  if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS") || std::getenv("OMP_NUM_THREADS"))
    GTEST_SKIP() << "thread count given by the environment";
  EXPECT_EQ(lunaster::engine::blas_threads(), lunaster::engine::kBlasThreads);
  (void)lunaster::engine::make_linear_solver(lunaster::engine::SolverKind::Cholmod);  // configures again: no change
  EXPECT_EQ(lunaster::engine::blas_threads(), lunaster::engine::kBlasThreads);
}

TEST_F(Blas, IdleWorkersSleepWithinMilliseconds) {
  // OpenBLAS's default, 2^28 cycles of sched_yield before an idle worker sleeps, is replaced by
  // 2^20 unless the environment names one; the environment is left as it was.
  if (std::getenv("OPENBLAS_THREAD_TIMEOUT")) GTEST_SKIP() << "timeout given by the environment";
  using Timeout = int (*)();
  const auto timeout = reinterpret_cast<Timeout>(dlsym(RTLD_DEFAULT, "openblas_thread_timeout"));
  if (!timeout) GTEST_SKIP() << "this OpenBLAS does not export openblas_thread_timeout";
  EXPECT_EQ(timeout(), 20);
  EXPECT_EQ(std::getenv("OPENBLAS_THREAD_TIMEOUT"), nullptr);
}

TEST_F(Blas, CholmodRegionsRunWithoutATeam) {
  // CHOLMOD's supernodal factorisation opens OpenMP regions around its scatter loops; they bind
  // to lunaster's GOMP_parallel, which runs them on the calling thread, and the factor is right.
  if (std::getenv("OMP_MAX_ACTIVE_LEVELS") || std::getenv("OMP_THREAD_LIMIT"))
    GTEST_SKIP() << "OpenMP set by the environment";
  const int n = 40, size = n * n * n;  // 3D Laplacian: large supernodes
  auto at = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int r = at(i, j, k);
        t.emplace_back(r, r, 6.1);
        if (i + 1 < n) t.emplace_back(r, at(i + 1, j, k), -1.0), t.emplace_back(at(i + 1, j, k), r, -1.0);
        if (j + 1 < n) t.emplace_back(r, at(i, j + 1, k), -1.0), t.emplace_back(at(i, j + 1, k), r, -1.0);
        if (k + 1 < n) t.emplace_back(r, at(i, j, k + 1), -1.0), t.emplace_back(at(i, j, k + 1), r, -1.0);
      }
  lunaster::engine::SparseMatrix a(size, size);
  a.setFromTriplets(t.begin(), t.end());
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(size, -1.0, 2.0), b = a * x;
  const long before = lunaster::engine::openmp_regions_inlined();
  auto solver = lunaster::engine::make_linear_solver(lunaster::engine::SolverKind::Cholmod);
  solver->factorize(a, lunaster::engine::MatrixKind::SymmetricPositiveDefinite);
  EXPECT_GT(lunaster::engine::openmp_regions_inlined(), before);
  EXPECT_LT((solver->solve(b) - x).norm(), 1e-12 * x.norm());
}

MatrixXd random(int r, int c, int seed) {
  MatrixXd m(r, c);
  for (int j = 0; j < c; ++j)
    for (int i = 0; i < r; ++i) m(i, j) = std::sin(0.37 * i + 1.3 * j + seed) + 0.01 * seed;
  return m;
}

TEST_F(Blas, TwoThreadsForAWideCallThenOneAgain) {
  // A 3D supernodal factorisation runs its dense kernels on two threads (WideBlas), and the
  // run goes back to one thread after it, whose dgemm gives the same product as before.
  if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS") || std::getenv("OMP_NUM_THREADS"))
    GTEST_SKIP() << "thread count given by the environment";
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one core";
  using lunaster::engine::blas_threads;
  const MatrixXd a = random(300, 300, 1), b = random(300, 300, 2), ref = a * b;
  auto gemm = [&] {
    MatrixXd c = MatrixXd::Zero(300, 300);
    const int n = 300;
    const double one = 1.0, zero = 0.0;
    dgemm_("N", "N", &n, &n, &n, &one, a.data(), &n, b.data(), &n, &zero, c.data(), &n);
    return (c - ref).norm() / ref.norm();
  };
  {
    const lunaster::engine::WideBlas wide(false);
    EXPECT_EQ(blas_threads(), 1);
  }
  {
    const lunaster::engine::WideBlas wide(true);
    EXPECT_EQ(blas_threads(), 2);
    EXPECT_LT(gemm(), 1e-14);
  }
  EXPECT_EQ(blas_threads(), 1);
  EXPECT_LT(gemm(), 1e-14);
}

TEST_F(Blas, GemmAllTransposes) {
  for (int size : {7, 180}) {
    const int m = size, n = size + 3, k = size / 2 + 5;
    for (const char* ta : {"N", "T"})
      for (const char* tb : {"N", "T"}) {
        const bool at = *ta == 'T', bt = *tb == 'T';
        const MatrixXd a = random(at ? k : m, at ? m : k, 1), b = random(bt ? n : k, bt ? k : n, 2);
        MatrixXd c = random(m + 2, n, 3);  // ldc = m + 2
        MatrixXd ref = c;
        const MatrixXd opa = at ? MatrixXd(a.transpose()) : a, opb = bt ? MatrixXd(b.transpose()) : b;
        ref.topRows(m) = 0.5 * c.topRows(m) - 1.5 * opa * opb;
        const double alpha = -1.5, beta = 0.5;
        const int lda = static_cast<int>(a.rows()), ldb = static_cast<int>(b.rows()), ldc = m + 2;
        dgemm_(ta, tb, &m, &n, &k, &alpha, a.data(), &lda, b.data(), &ldb, &beta, c.data(), &ldc);
        EXPECT_LT((c - ref).norm(), 1e-11 * ref.norm()) << ta << tb << " " << size;
      }
  }
}

TEST_F(Blas, SyrkLowerUpper) {
  const int n = 40, k = 17;
  for (const char* uplo : {"L", "U"})
    for (const char* tr : {"N", "T"}) {
      const bool t = *tr == 'T';
      const MatrixXd a = random(t ? k : n, t ? n : k, 4);
      MatrixXd c = random(n, n, 5);
      const MatrixXd opa = t ? MatrixXd(a.transpose()) : a;
      const MatrixXd full = 2.0 * c - 0.5 * opa * opa.transpose();
      const double alpha = -0.5, beta = 2.0;
      const int lda = static_cast<int>(a.rows());
      const MatrixXd before = c;
      dsyrk_(uplo, tr, &n, &k, &alpha, a.data(), &lda, &beta, c.data(), &n);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const bool in = *uplo == 'L' ? i >= j : i <= j;
          EXPECT_NEAR(c(i, j), in ? full(i, j) : before(i, j), 1e-12) << uplo << tr;
        }
    }
}

TEST_F(Blas, TrsmEveryVariant) {
  for (int size : {9, 200}) {
    const int m = size, n = size / 3 + 4;
    for (const char* side : {"L", "R"})
      for (const char* uplo : {"L", "U"})
        for (const char* tr : {"N", "T"})
          for (const char* diag : {"N", "U"}) {
            const int na = *side == 'L' ? m : n;
            MatrixXd a = random(na, na, 6) / na;  // small off-diagonals: well conditioned even with a unit diagonal
            a.diagonal().array() += 3.0;
            MatrixXd tri = *uplo == 'L' ? MatrixXd(a.triangularView<Eigen::Lower>()) : MatrixXd(a.triangularView<Eigen::Upper>());
            if (*diag == 'U') tri.diagonal().setOnes();
            const MatrixXd op = *tr == 'T' ? MatrixXd(tri.transpose()) : tri;
            const MatrixXd b0 = random(m, n, 7);
            MatrixXd b = b0;
            const double alpha = 1.25;
            dtrsm_(side, uplo, tr, diag, &m, &n, &alpha, a.data(), &na, b.data(), &m);
            const MatrixXd back = *side == 'L' ? MatrixXd(op * b) : MatrixXd(b * op);
            EXPECT_LT((back - alpha * b0).norm(), 1e-10 * b0.norm()) << side << uplo << tr << diag << size;
          }
  }
}

TEST_F(Blas, PotrfFactorsAndReportsTheFailingMinor) {
  const int n = 30;
  MatrixXd a = random(n, n, 8);
  MatrixXd spd = a * a.transpose() + n * MatrixXd::Identity(n, n);
  MatrixXd l = spd;
  int info = -1;
  dpotrf_("L", &n, l.data(), &n, &info);
  EXPECT_EQ(info, 0);
  const MatrixXd low = l.triangularView<Eigen::Lower>();
  EXPECT_LT((low * low.transpose() - spd).norm(), 1e-10 * spd.norm());
  MatrixXd u = spd;
  dpotrf_("U", &n, u.data(), &n, &info);
  EXPECT_EQ(info, 0);
  const MatrixXd up = u.triangularView<Eigen::Upper>();
  EXPECT_LT((up.transpose() * up - spd).norm(), 1e-10 * spd.norm());
  MatrixXd bad = spd;
  bad(4, 4) = -1.0;  // leading minor of order 5 is indefinite
  dpotrf_("L", &n, bad.data(), &n, &info);
  EXPECT_EQ(info, 5);
}

TEST_F(Blas, GemvAndTrsv) {
  const int m = 25, n = 19;
  const MatrixXd a = random(m, n, 9);
  const Eigen::VectorXd x = random(m, 1, 10);  // long enough for both shapes
  Eigen::VectorXd y = random(m, 1, 11);
  const Eigen::VectorXd ref_n = 0.5 * y + 2.0 * a * x.head(n);
  const double alpha = 2.0, beta = 0.5;
  const int one = 1;
  dgemv_("N", &m, &n, &alpha, a.data(), &m, x.data(), &one, &beta, y.data(), &one);
  EXPECT_LT((y - ref_n).norm(), 1e-12 * ref_n.norm());
  Eigen::VectorXd yt = random(n, 1, 12);
  const Eigen::VectorXd ref_t = 0.5 * yt + 2.0 * a.transpose() * x;
  dgemv_("T", &m, &n, &alpha, a.data(), &m, x.data(), &one, &beta, yt.data(), &one);
  EXPECT_LT((yt - ref_t).norm(), 1e-12 * ref_t.norm());
  MatrixXd t = random(n, n, 13);
  t.diagonal().array() += 2.0 * n;
  for (const char* uplo : {"L", "U"})
    for (const char* tr : {"N", "T"}) {
      MatrixXd tri = *uplo == 'L' ? MatrixXd(t.triangularView<Eigen::Lower>()) : MatrixXd(t.triangularView<Eigen::Upper>());
      const MatrixXd op = *tr == 'T' ? MatrixXd(tri.transpose()) : tri;
      Eigen::VectorXd v = x.head(n);
      dtrsv_(uplo, tr, "N", &n, t.data(), &n, v.data(), &one);
      EXPECT_LT((op * v - x.head(n)).norm(), 1e-12 * x.norm()) << uplo << tr;
    }
}

}  // namespace
