// The saddle-point backend (engine/solver/saddle_solver.hpp): contact-like systems
// [A B^T; B C] solved through CHOLMOD on the multipliers' Schur complement and GMRES, against
// a known solution; and the cases it hands to the direct backend.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/solver/saddle_solver.hpp"

namespace lunaster::engine {
namespace {

/// A 3D grid Laplacian (n^3 displacement equations, SPD) and `m` multiplier equations
/// after them. Multiplier k ties two far-apart equations (a "gap" row: u_i - u_j, scaled
/// like a stiffness); the first `inactive` multipliers have no constraint row but a
/// negative mass-like block instead (C: -2/3 on the diagonal, -1/6 between neighbours), as
/// an inactive CONTINUE point's multipliers have. `bend` puts an indefinite 2 x 2 block in A.
SparseMatrix saddle_system(int n, int m, int inactive, bool bend = false) {
  const int nu = n * n * n, size = nu + m;
  auto at = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  std::vector<Triplet> t;
  auto sym = [&t](int r, int c, double v) { t.emplace_back(r, c, v), t.emplace_back(c, r, v); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int r = at(i, j, k);
        t.emplace_back(r, r, 6.2e3);
        if (i + 1 < n) sym(r, at(i + 1, j, k), -1e3);
        if (j + 1 < n) sym(r, at(i, j + 1, k), -1e3);
        if (k + 1 < n) sym(r, at(i, j, k + 1), -1e3);
      }
  if (bend) sym(0, 1, 2e4);  // [[6.2e3, 1.9e4], [1.9e4, 6.2e3]]: A is indefinite
  for (int q = 0; q < m; ++q) {
    const int l = nu + q;
    if (q < inactive) {
      t.emplace_back(l, l, -2.0 / 3.0);
      if (q + 1 < inactive) sym(l, l + 1, -1.0 / 6.0);
      sym(l, at(q % n, 0, 0), 0.0);  // a stored zero: the pattern of an active point
      continue;
    }
    sym(l, at(q % n, (q / n) % n, 0), 2e3);
    sym(l, at(q % n, (q / n) % n, n - 1), -2e3);
    t.emplace_back(l, l, 0.0);
  }
  SparseMatrix a(size, size);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

Vector known(Eigen::Index size) {
  Vector x(size);
  for (Eigen::Index i = 0; i < size; ++i) x[i] = std::sin(0.37 * static_cast<double>(i)) + 0.1;
  return x;
}

TEST(SaddleSolver, SolvesAContactLikeSystemThroughCholmod) {
  const SparseMatrix a = saddle_system(16, 120, 30);
  const Vector x = known(a.rows()), b = a * x;
  std::vector<std::string> notes;
  auto solver = make_saddle_solver(SolverKind::Mumps, [&notes](const std::string& s) { notes.push_back(s); });
  solver->factorize(a, MatrixKind::SymmetricIndefinite);
  const Vector y = solver->solve(b);
  EXPECT_LT((y - x).norm(), 1e-10 * x.norm());
  EXPECT_LT((a * y - b).norm(), 1e-12 * b.norm());
  EXPECT_NE(solver->name().find("CHOLMOD"), std::string::npos) << solver->name();
  EXPECT_GT(solver->iterations(), 0);
  EXPECT_LE(solver->iterations(), 12);  // the preconditioner is the system to about 1e-6
  EXPECT_TRUE(notes.empty());
  // A second right-hand side with the same factorisation.
  const Vector y2 = solver->solve(2.0 * b);
  EXPECT_LT((y2 - 2.0 * x).norm(), 2e-10 * x.norm());
}

TEST(SaddleSolver, AnIndefiniteDisplacementBlockGoesToTheDirectBackend) {
  const SparseMatrix a = saddle_system(8, 20, 0, true);
  const Vector x = known(a.rows()), b = a * x;
  std::vector<std::string> notes;
  auto solver = make_saddle_solver(SolverKind::Mumps, [&notes](const std::string& s) { notes.push_back(s); });
  solver->factorize(a, MatrixKind::SymmetricIndefinite);
  EXPECT_LT((solver->solve(b) - x).norm(), 1e-10 * x.norm());
  EXPECT_EQ(solver->name(), "MUMPS");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("not positive definite"), std::string::npos) << notes[0];
  // From then on the direct backend, without trying again or saying it twice.
  const SparseMatrix c = saddle_system(8, 20, 5);
  const Vector xc = known(c.rows());
  solver->factorize(c, MatrixKind::SymmetricIndefinite);
  EXPECT_LT((solver->solve(c * xc) - xc).norm(), 1e-10 * xc.norm());
  EXPECT_EQ(solver->name(), "MUMPS");
  EXPECT_EQ(notes.size(), 1u);
}

TEST(SaddleSolver, SystemsWithoutMultipliersGoToTheDirectBackendSilently) {
  // No equation with a non-positive diagonal: nothing to split.
  const SparseMatrix spd = saddle_system(6, 0, 0);
  const Vector x = known(spd.rows());
  std::vector<std::string> notes;
  auto solver = make_saddle_solver(SolverKind::Mumps, [&notes](const std::string& s) { notes.push_back(s); });
  solver->factorize(spd, MatrixKind::SymmetricIndefinite);
  EXPECT_LT((solver->solve(spd * x) - x).norm(), 1e-10 * x.norm());
  EXPECT_EQ(solver->name(), "MUMPS");
  // And a system with the saddle structure afterwards is split after all.
  const SparseMatrix s = saddle_system(10, 40, 10);
  const Vector xs = known(s.rows());
  solver->factorize(s, MatrixKind::SymmetricIndefinite);
  EXPECT_LT((solver->solve(s * xs) - xs).norm(), 1e-10 * xs.norm());
  EXPECT_NE(solver->name().find("CHOLMOD"), std::string::npos);
  EXPECT_TRUE(notes.empty());
}

}  // namespace
}  // namespace lunaster::engine
