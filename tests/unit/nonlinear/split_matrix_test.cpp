// split_matrix: the Newton driver keeps the elastic stiffness only as K(F, F) and the
// constrained columns K(:, C). They must be exactly the restricted matrix and K's columns,
// and give K u over the whole numbering (the residual and its reactions).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/nonlinear/reduction.hpp"

namespace lunaster::engine {
namespace {

/// A symmetric matrix of order n with a scattered pattern and a dominant diagonal.
SparseMatrix symmetric_matrix(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, 10.0 + value(gen));
  for (int k = 0; k < 4 * n; ++k) {
    const int i = pick(gen), j = pick(gen);
    const double v = value(gen);
    t.emplace_back(i, j, v);
    t.emplace_back(j, i, v);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

void check_split(const SparseMatrix& k, const std::vector<int>& constrained, const std::string& what) {
  const int n = static_cast<int>(k.rows());
  std::vector<int> sorted = constrained;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::vector<int> free_index(n, 0);
  for (int eq : sorted) free_index[eq] = -1;
  int nf = 0;
  for (int eq = 0; eq < n; ++eq)
    if (free_index[eq] == 0) free_index[eq] = nf++;
  const SparseMatrix ref = restrict_matrix(k, free_index, nf);

  SparseMatrix consumed = k;
  SplitMatrix s;
  split_matrix(consumed, constrained, s);
  EXPECT_EQ(consumed.nonZeros(), 0) << what;
  EXPECT_EQ(s.constrained, sorted) << what;
  EXPECT_EQ(s.free_index, free_index) << what;
  ASSERT_EQ(static_cast<int>(s.equation.size()), nf) << what;
  for (int j = 0; j < nf; ++j) EXPECT_EQ(free_index[s.equation[j]], j) << what;
  // K(F, F): the restricted matrix, entry for entry.
  ASSERT_TRUE(s.ff.isCompressed()) << what;
  ASSERT_EQ(s.ff.rows(), nf) << what;
  ASSERT_EQ(s.ff.cols(), nf) << what;
  ASSERT_EQ(s.ff.nonZeros(), ref.nonZeros()) << what;
  EXPECT_TRUE(std::equal(ref.outerIndexPtr(), ref.outerIndexPtr() + nf + 1, s.ff.outerIndexPtr())) << what;
  EXPECT_TRUE(std::equal(ref.innerIndexPtr(), ref.innerIndexPtr() + ref.nonZeros(), s.ff.innerIndexPtr())) << what;
  EXPECT_TRUE(std::equal(ref.valuePtr(), ref.valuePtr() + ref.nonZeros(), s.ff.valuePtr())) << what;
  // K(:, C): K's constrained columns, every row.
  ASSERT_EQ(s.c.rows(), n) << what;
  ASSERT_EQ(s.c.cols(), static_cast<int>(sorted.size())) << what;
  for (size_t c = 0; c < sorted.size(); ++c) {
    SparseMatrix::InnerIterator a(k, sorted[c]), b(s.c, static_cast<int>(c));
    for (; a && b; ++a, ++b) {
      EXPECT_EQ(a.row(), b.row()) << what;
      EXPECT_EQ(a.value(), b.value()) << what;
    }
    EXPECT_FALSE(a || b) << what << ": column " << sorted[c] << " has another length";
  }
  // K u over the whole numbering, constrained rows (the reactions) included.
  Vector u(n);
  for (int i = 0; i < n; ++i) u[i] = std::sin(1.3 * i + 0.2) + (i % 7 == 0 ? 5.0 : 0.0);
  const Vector expected = k * u;
  const Vector ku = s.times(u);
  const double scale = k.cwiseAbs().sum() * u.cwiseAbs().maxCoeff();
  for (int i = 0; i < n; ++i) EXPECT_NEAR(ku[i], expected[i], 1e-14 * scale) << what << ": row " << i;
}

TEST(SplitMatrix, GivesTheRestrictedMatrixTheConstrainedColumnsAndKu) {
  const SparseMatrix k = symmetric_matrix(60, 7);
  check_split(k, {41, 3, 17, 3, 59, 0, 22, 23}, "unsorted, repeated constraints");
  check_split(k, {}, "nothing constrained");
  std::vector<int> all(60);
  for (int i = 0; i < 60; ++i) all[i] = 59 - i;
  check_split(k, all, "everything constrained");
  std::vector<int> half;
  for (int i = 0; i < 60; i += 2) half.push_back(i);
  check_split(symmetric_matrix(60, 11), half, "every second equation");
}

}  // namespace
}  // namespace lunaster::engine
