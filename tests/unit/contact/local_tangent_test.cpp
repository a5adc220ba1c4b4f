// LocalTangent: summing contact terms per slave cell must give the same matrix as one
// triplet per term, including when a cell touches more DOFs than the first allocation.
#include <random>

#include <cmath>

#include <gtest/gtest.h>

#include "engine/contact/linear_gap.hpp"

using namespace lunaster::engine;
using namespace lunaster::engine::contact;

namespace {

LinearGap random_gap(std::mt19937& gen, int n_eq, int n_terms) {
  std::uniform_int_distribution<int> eq(0, n_eq - 1);
  std::uniform_real_distribution<double> c(-1.0, 1.0);
  LinearGap g;
  g.n = n_terms;
  for (int k = 0; k < n_terms; ++k) g.eq[k] = eq(gen), g.coef[k] = c(gen);  // repeated eqs allowed
  return g;
}

SparseMatrix to_matrix(const std::vector<Triplet>& t, int n) {
  SparseMatrix m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

}  // namespace

TEST(LocalTangent, SumsToTheSameMatrixAsOneTripletPerTerm) {
  for (int n_eq : {20, 300}) {  // 300 forces the accumulator to grow past 64 and 128 DOFs
    std::mt19937 gen(n_eq);
    std::uniform_real_distribution<double> w(0.1, 2.0);
    std::vector<Triplet> direct, summed;
    LocalTangent local;
    for (int cell = 0; cell < 5; ++cell) {
      for (int point = 0; point < 40; ++point) {
        const LinearGap a = random_gap(gen, n_eq, LinearGap::kMaxTerms), b = random_gap(gen, n_eq, 7);
        const double f = w(gen);
        local.add_outer(a, b, f);
        for (int i = 0; i < a.n; ++i)
          for (int j = 0; j < b.n; ++j) direct.emplace_back(a.eq[i], b.eq[j], f * a.coef[i] * b.coef[j]);
        local.add(b.eq[0], a.eq[3], f);
        direct.emplace_back(b.eq[0], a.eq[3], f);
      }
      local.flush(summed);
    }
    const SparseMatrix d = to_matrix(direct, n_eq), s = to_matrix(summed, n_eq);
    EXPECT_LT((Eigen::MatrixXd(d) - Eigen::MatrixXd(s)).cwiseAbs().maxCoeff(), 1e-12 * Eigen::MatrixXd(d).cwiseAbs().maxCoeff());
    // Points sharing their DOFs (the real case) give far fewer triplets.
    if (n_eq == 20) {
      EXPECT_LT(summed.size(), direct.size() / 20);
    }
  }
}

TEST(LocalTangent, FlushEmptiesTheAccumulator) {
  LocalTangent local;
  std::vector<Triplet> out;
  local.add(3, 4, 2.5);
  local.flush(out);
  // Only the entry touched.
  ASSERT_EQ(out.size(), 1u);
  double sum = 0.0;
  for (const auto& t : out) {
    EXPECT_TRUE((t.row() == 3 || t.row() == 4) && (t.col() == 3 || t.col() == 4));
    if (t.row() == 3 && t.col() == 4) {
      EXPECT_DOUBLE_EQ(t.value(), 2.5);
    }
    sum += std::abs(t.value());
  }
  EXPECT_DOUBLE_EQ(sum, 2.5);
  local.flush(out);  // nothing left to emit
  EXPECT_EQ(out.size(), 1u);
  local.add(3, 4, 1.0);  // a fresh sum, not 3.5
  local.flush(out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(out[1].value(), 1.0);
}

TEST(LocalTangent, PatternDoesNotDependOnTheValues) {
  // The same adds with other values (zeros among them) give the same positions in the
  // same order: the driver keeps its system pattern while contact statuses change.
  LinearGap g;
  g.n = 3;
  g.eq = {7, 2, 9};
  g.coef = {1.0, -0.5, 0.25};
  std::vector<Triplet> a, b;
  for (double factor : {2.0, 0.0}) {
    LocalTangent local;
    local.add_outer(g, g, factor);
    local.add(11, 7, factor);
    local.flush(factor != 0.0 ? a : b);
  }
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), 10u);  // the 3 x 3 outer product and (11, 7), zeros included
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].row(), b[k].row());
    EXPECT_EQ(a[k].col(), b[k].col());
    EXPECT_EQ(b[k].value(), 0.0);
  }
}
