// An unsymmetric system (what a frictional law's tangent gives) through the driver's linear
// solve (LinearSolve): MatrixKind::General goes to an LU factorisation, UMFPACK on a small
// system of one process whatever SPD backend the run named, MUMPS unsymmetric (SYM=0) when the
// run names MUMPS, and the solve matches an independent sparse LU of the whole matrix. A
// factorisation that read one triangle only (Cholesky, or MUMPS symmetric) would solve the
// symmetric part instead: the skew part below changes the solution at order 1.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include <Eigen/SparseLU>

#include "engine/core/log.hpp"
#include "engine/nonlinear/linear_solve.hpp"

namespace lunaster::engine {
namespace {

/// A 1D convection-diffusion operator on n unknowns: diffusion (2, -1) plus a convection
/// (+-c/2) that makes it unsymmetric; regular for any c (diagonally dominant for c < 2).
SparseMatrix convection_diffusion(int n, double c) {
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0);
    if (i > 0) t.emplace_back(i, i - 1, -1.0 - 0.5 * c);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0 + 0.5 * c);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

struct Solved {
  SolverKind backend;
  LinearSolve::BackendNote note;
  Vector x;
  std::vector<MatrixKind> factorised;  ///< the kinds handed to a factorisation
};

Solved solve_through_driver(NewtonOptions options, const SparseMatrix& a, const Vector& b) {
  SolverStats stats;
  std::ostringstream sink;
  Log log(sink, 1);
  LinearSolve linear(options, stats, log);
  Solved out;
  const LinearSolve::Backend chosen = linear.choose(MatrixKind::General, static_cast<int>(a.rows()), 2, false);
  out.backend = chosen.kind;
  out.note = chosen.note;
  LinearSolve::System system;
  system.a = &a;
  system.kind = MatrixKind::General;
  system.pattern = 1;
  system.values_key = 1;
  system.product = [&a](const Vector& x) -> Vector { return a * x; };
  system.observe = [&out](const SparseMatrix&, MatrixKind kind) { out.factorised.push_back(kind); };
  system.diagnose = [](const SolveError& err) { return err; };
  const LinearSolve::Events events = [](const LinearSolve::Event&) {};
  RefinedSolve accuracy;
  out.x = linear.solve(linear.backend(chosen.kind, events), linear.state(chosen.kind), chosen.kind, system, b, events,
                       accuracy);
  return out;
}

TEST(UnsymmetricSolve, GeneralSystemsGoToAnLuFactorisationAndSolveExactly) {
  const int n = 60;
  const SparseMatrix a = convection_diffusion(n, 1.5);
  Vector b(n);
  for (int i = 0; i < n; ++i) b[i] = std::sin(0.3 * i) + 1.0;
  Eigen::SparseLU<SparseMatrix> lu(a);
  ASSERT_EQ(lu.info(), Eigen::Success);
  const Vector reference = lu.solve(b);
  // The solution of the symmetric part differs at order 1: reading one triangle would show.
  Eigen::SparseLU<SparseMatrix> sym_lu(SparseMatrix(0.5 * (a + SparseMatrix(a.transpose()))));
  ASSERT_GT((Vector(sym_lu.solve(b)) - reference).norm(), 0.1 * reference.norm());

  NewtonOptions cholmod;  // the default: CHOLMOD, which factorises SPD systems only
  const Solved by_default = solve_through_driver(cholmod, a, b);
  EXPECT_EQ(by_default.backend, SolverKind::Umfpack);
  EXPECT_EQ(by_default.note, LinearSolve::BackendNote::Umfpack);
  EXPECT_EQ(by_default.factorised, std::vector<MatrixKind>{MatrixKind::General});
  EXPECT_LE((by_default.x - reference).norm(), 1e-12 * reference.norm());

  NewtonOptions mumps;
  mumps.solver = SolverKind::Mumps;
  const Solved by_mumps = solve_through_driver(mumps, a, b);
  EXPECT_EQ(by_mumps.backend, SolverKind::Mumps);
  EXPECT_EQ(by_mumps.factorised, std::vector<MatrixKind>{MatrixKind::General});
  EXPECT_LE((by_mumps.x - reference).norm(), 1e-12 * reference.norm());
}

}  // namespace
}  // namespace lunaster::engine
