// Linear solver backends against a dense Eigen solve; singular matrices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <SuiteSparse_config.h>
#include <cholmod.h>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/equation_name.hpp"
#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"
#include "engine/solver/backends.hpp"
#include "engine/solver/interface_solver.hpp"
#include "engine/solver/linear_solver.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::expect_close;

/// 1D Laplacian-like SPD matrix with a Dirichlet shift, plus off-diagonal coupling.
SparseMatrix spd_matrix(int n) {
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4.0 + 0.1 * i);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -1.0);
    }
    if (i + 3 < n) {
      t.emplace_back(i, i + 3, -0.5);
      t.emplace_back(i + 3, i, -0.5);
    }
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

/// Saddle point [K B^T; B 0]: K SPD (n x n), B two constraint rows.
SparseMatrix saddle_matrix(int n) {
  const SparseMatrix k = spd_matrix(n);
  std::vector<Triplet> t;
  for (int c = 0; c < k.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(k, c); it; ++it) t.emplace_back(it.row(), c, it.value());
  const double b[2][3] = {{1.0, -1.0, 0.5}, {0.3, 2.0, -1.0}};
  for (int r = 0; r < 2; ++r)
    for (int j = 0; j < 3; ++j) {
      const int col = 2 * j + r;
      t.emplace_back(n + r, col, b[r][j]);
      t.emplace_back(col, n + r, b[r][j]);
    }
  SparseMatrix a(n + 2, n + 2);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

Vector rhs(int n) {
  Vector b(n);
  for (int i = 0; i < n; ++i) b(i) = std::sin(0.7 * i) + 0.1 * i;
  return b;
}

void check_solution(const SparseMatrix& a, const Vector& x, const std::string& what) {
  const Vector ref = Eigen::MatrixXd(a).fullPivLu().solve(rhs(static_cast<int>(a.rows())));
  for (int i = 0; i < x.size(); ++i) expect_close(x(i), ref(i), 1e-10, 1e-12, what);
}

TEST(Solvers, SpdSystemEveryBackend) {
  const SparseMatrix a = spd_matrix(40);
  for (SolverKind kind : {SolverKind::Cholmod, SolverKind::Umfpack, SolverKind::Mumps}) {
    auto s = make_linear_solver(kind);
    s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
    check_solution(a, s->solve(rhs(40)), s->name());
    EXPECT_EQ(s->failed_column(), -1);
    // a second factorisation with the same pattern and new values
    const SparseMatrix a2 = 2.0 * a;
    s->factorize(a2, MatrixKind::SymmetricPositiveDefinite);
    check_solution(a2, s->solve(rhs(40)), s->name() + " refactorised");
  }
}

TEST(Solvers, SaddlePointSystemIndefiniteBackends) {
  const SparseMatrix a = saddle_matrix(30);
  for (SolverKind kind : {SolverKind::Umfpack, SolverKind::Mumps}) {
    auto s = make_linear_solver(kind);
    s->factorize(a, MatrixKind::SymmetricIndefinite);
    check_solution(a, s->solve(rhs(32)), s->name() + " indefinite");
    s->factorize(a, MatrixKind::General);
    check_solution(a, s->solve(rhs(32)), s->name() + " general");
  }
  auto cholmod = make_linear_solver(SolverKind::Cholmod);
  EXPECT_THROW(cholmod->factorize(a, MatrixKind::SymmetricIndefinite), InternalError);
}

TEST(InterfaceSolver, ContactPassesOnTheKeptElasticFactorisation) {
  // The saddle point's multipliers (30, 31) and the displacements they couple (0..5), plus
  // 7 and 12 (interface nodes without contact terms yet): the interface. K, the elastic part,
  // stores zero diagonals on the multipliers, as the driver's does.
  const int n = 30;
  const std::vector<int> interface = {0, 1, 2, 3, 4, 5, 7, 12, n, n + 1};
  SparseMatrix a = saddle_matrix(n);
  SparseMatrix diag(n + 2, n + 2);
  diag.insert(n, n) = 1.0;
  diag.insert(n + 1, n + 1) = 1.0;
  a = a + 0.0 * diag;  // stored zero diagonals on the multipliers
  a.makeCompressed();
  SparseMatrix k = a;  // the elastic part: zeros where contact terms go
  for (int c = 0; c < k.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(k, c); it; ++it)
      if (it.row() >= n || c >= n) it.valueRef() = 0.0;
  const SparseMatrix k_before = k;
  auto solver = make_interface_solver(interface);
  EXPECT_TRUE(solver->factorize_reference(k, 0.0));
  EXPECT_EQ((k - k_before).norm(), 0.0);  // the unit diagonals were given back
  // Each pass gets the contact terms alone, C = A - K.
  solver->factorize(a - k, MatrixKind::SymmetricIndefinite);
  check_solution(a, solver->solve(rhs(n + 2)), "interface solver, saddle point");
  // Another pass: new contact values on the II block only (a penalty on the coupled
  // displacements), the reference kept.
  SparseMatrix a2 = a;
  for (int c = 0; c < 6; ++c) a2.coeffRef(c, c) += 50.0 * (c + 1);
  solver->factorize(a2 - k, MatrixKind::SymmetricIndefinite);
  check_solution(a2, solver->solve(rhs(n + 2)), "interface solver, second pass");
  // The pass without contact: the multipliers decoupled (unit diagonal), the elastic solve.
  SparseMatrix a3 = k;
  a3.coeffRef(n, n) = a3.coeffRef(n + 1, n + 1) = 1.0;
  solver->factorize(a3 - k, MatrixKind::SymmetricPositiveDefinite);
  check_solution(a3, solver->solve(rhs(n + 2)), "interface solver, no contact");
  // Terms outside the interface are not read: the answer is K + C_II's.
  SparseMatrix outside = a2 - k;
  outside.coeffRef(20, 20) += 1e3;
  solver->factorize(outside, MatrixKind::SymmetricIndefinite);
  check_solution(a2, solver->solve(rhs(n + 2)), "interface solver, terms outside the interface");
}

TEST(InterfaceSolver, AReferenceThatIsNotPositiveDefiniteIsRefused) {
  SparseMatrix k = spd_matrix(12);
  k.coeffRef(11, 11) = -1.0;  // an interior equation breaks positivity
  auto solver = make_interface_solver({0, 1});
  EXPECT_THROW(solver->factorize_reference(k, 0.0), SolveError);
  EXPECT_THROW(solver->factorize(k, MatrixKind::SymmetricIndefinite), InternalError);
}

/// PETSc settings with a tolerance tight enough to compare with a direct solve.
IterativeSettings petsc(IterativeSettings::Krylov krylov, IterativeSettings::Preconditioner pc, int max_iterations = 0) {
  IterativeSettings s;
  s.krylov = krylov;
  s.preconditioner = pc;
  s.relative_residual = 1e-13;
  s.max_iterations = max_iterations;
  return s;
}

TEST(Solvers, PetscKrylovEveryPreconditionerOnSpd) {
  using S = IterativeSettings;
  const SparseMatrix a = spd_matrix(60);
  for (S::Preconditioner pc : {S::Preconditioner::Gamg, S::Preconditioner::Ml, S::Preconditioner::Boomer,
                               S::Preconditioner::LdltSp, S::Preconditioner::Jacobi, S::Preconditioner::None}) {
    auto s = make_linear_solver(SolverKind::Petsc, petsc(S::Krylov::CG, pc));
    EXPECT_TRUE(s->iterative());
    s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
    check_solution(a, s->solve(rhs(60)), s->name());
    EXPECT_GT(s->iterations(), 0) << s->name();
  }
  // SOR is not symmetric: GMRES.
  auto sor = make_linear_solver(SolverKind::Petsc, petsc(S::Krylov::GMRES, S::Preconditioner::Sor));
  sor->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  check_solution(a, sor->solve(rhs(60)), sor->name());
}

TEST(Solvers, PetscTakesTheMatrixAndMultipliesByItsCopy) {
  // A caller that needs the matrix only through products hands it over: PETSc keeps its
  // copy, the caller's storage is released (its size kept), and the product is A x.
  using S = IterativeSettings;
  const SparseMatrix a = spd_matrix(50);
  for (S::Preconditioner pc : {S::Preconditioner::Boomer, S::Preconditioner::LdltSp}) {
    SparseMatrix taken = a;
    auto s = make_linear_solver(SolverKind::Petsc, petsc(S::Krylov::CG, pc));
    Vector y;
    EXPECT_FALSE(s->multiply(rhs(50), y)) << "no product before a matrix is given";
    EXPECT_TRUE(s->factorize_taking(taken, MatrixKind::SymmetricPositiveDefinite));
    EXPECT_EQ(taken.nonZeros(), 0);
    EXPECT_EQ(taken.rows(), 50);
    EXPECT_EQ(taken.cols(), 50);
    check_solution(a, s->solve(rhs(50)), s->name() + " after taking the matrix");
    ASSERT_TRUE(s->multiply(rhs(50), y));
    const Vector ref = a * rhs(50);
    for (int i = 0; i < 50; ++i) expect_close(y(i), ref(i), 1e-14, 1e-14, s->name() + " product");
  }
  // A direct backend keeps the caller's matrix and has no product of its own.
  SparseMatrix kept = a;
  auto direct = make_linear_solver(SolverKind::Cholmod);
  EXPECT_FALSE(direct->factorize_taking(kept, MatrixKind::SymmetricPositiveDefinite));
  EXPECT_EQ(kept.nonZeros(), a.nonZeros());
  Vector y;
  EXPECT_FALSE(direct->multiply(rhs(50), y));
}

TEST(Solvers, PetscKeepsTheSinglePrecisionFactorisationAsCodeAsterReacPrecondSays) {
  // REAC_PRECOND = 30 with LDLT_SP: after a solve of a few iterations the next matrix (A's
  // diagonal scaled by 1.001) is preconditioned by A's factorisation, kept, and still solved to
  // the tolerance. A matrix that factorisation no longer preconditions within 20 iterations
  // (A's diagonal scaled row by row by 1 to 181, ten different factors) is factorised during
  // its solve, which then converges, and that factorisation is kept in turn. A factorisation is
  // kept only for a matrix of the same size; after a solve that took more than REAC_PRECOND
  // iterations the next matrix is factorised, and REAC_PRECOND = 0 keeps none. With a kept
  // factorisation possible the caller keeps its matrix (factorize_taking returns false).
  using S = IterativeSettings;
  constexpr int n = 200;
  const SparseMatrix a = spd_matrix(n);
  auto scaled_diagonal = [&a](auto factor) {
    SparseMatrix m = a;
    for (int i = 0; i < n; ++i) m.coeffRef(i, i) *= factor(i);
    return m;
  };
  const SparseMatrix near = scaled_diagonal([](int) { return 1.001; });
  const SparseMatrix far = scaled_diagonal([](int i) { return 1.0 + 20.0 * (i % 10); });
  IterativeSettings settings = petsc(S::Krylov::FGMRES, S::Preconditioner::LdltSp, 20);
  settings.reac_precond = 30;
  auto s = make_linear_solver(SolverKind::Petsc, settings);
  SparseMatrix first = a;
  EXPECT_FALSE(s->factorize_taking(first, MatrixKind::SymmetricPositiveDefinite));
  EXPECT_EQ(first.nonZeros(), a.nonZeros());
  check_solution(a, s->solve(rhs(n)), s->name());
  EXPECT_EQ(s->name(), "PETSc FGMRES + single-precision LDL^T");
  s->factorize(near, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(s->name(), "PETSc FGMRES + single-precision LDL^T (kept from an earlier matrix)");
  check_solution(near, s->solve(rhs(n)), s->name());
  EXPECT_LE(s->iterations(), 20);
  s->factorize(far, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(s->name(), "PETSc FGMRES + single-precision LDL^T (kept from an earlier matrix)");
  check_solution(far, s->solve(rhs(n)), s->name());
  EXPECT_EQ(s->name(), "PETSc FGMRES + single-precision LDL^T (factorised again: the kept one did not converge)");
  EXPECT_GT(s->iterations(), 20);  // the kept factorisation's 20, then the solve on far's own
  s->factorize(far, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(s->name(), "PETSc FGMRES + single-precision LDL^T (kept from an earlier matrix)");  // far's own, kept
  check_solution(far, s->solve(rhs(n)), s->name());
  EXPECT_LE(s->iterations(), 5);
  const SparseMatrix smaller = spd_matrix(50);
  s->factorize(smaller, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(s->name(), "PETSc FGMRES + single-precision LDL^T");
  check_solution(smaller, s->solve(rhs(50)), s->name());

  settings.reac_precond = 1;  // a solve takes 2 iterations or more
  auto strict = make_linear_solver(SolverKind::Petsc, settings);
  strict->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  check_solution(a, strict->solve(rhs(n)), strict->name());
  EXPECT_GT(strict->iterations(), 1);
  strict->factorize(near, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(strict->name(), "PETSc FGMRES + single-precision LDL^T");

  auto every = make_linear_solver(SolverKind::Petsc, petsc(S::Krylov::FGMRES, S::Preconditioner::LdltSp, 20));
  every->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  every->solve(rhs(n));
  every->factorize(near, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(every->name(), "PETSc FGMRES + single-precision LDL^T");
}

TEST(Solvers, PetscSaddlePointNeedsAFactorisationAsPreconditioner) {
  using S = IterativeSettings;
  const SparseMatrix a = saddle_matrix(30);
  auto ok = make_linear_solver(SolverKind::Petsc, petsc(S::Krylov::FGMRES, S::Preconditioner::LdltSp));
  ok->factorize(a, MatrixKind::SymmetricIndefinite);
  check_solution(a, ok->solve(rhs(32)), ok->name());
  // Single precision preconditions: a few iterations, not one.
  EXPECT_GE(ok->iterations(), 1);
  EXPECT_LE(ok->iterations(), 6);
  for (auto [krylov, pc] : {std::pair{S::Krylov::CG, S::Preconditioner::LdltSp},
                            std::pair{S::Krylov::FGMRES, S::Preconditioner::Gamg}}) {
    auto s = make_linear_solver(SolverKind::Petsc, petsc(krylov, pc));
    try {
      s->factorize(a, MatrixKind::SymmetricIndefinite);
      ADD_FAILURE() << s->name() << " accepted a saddle point";
    } catch (const SolveError& e) {
      EXPECT_EQ(e.failure().what, Failure::What::IterativeSolve) << e.message();
      EXPECT_NE(e.message().find("saddle point"), std::string::npos) << e.message();
    }
  }
}

TEST(Solvers, AutoIterativeFallsBackToAFactorisation) {
  // SOLVEUR METHODE='AUTO' may pick CG for a large system; where CG fails, MUMPS factorises
  // the same matrix and the run goes on, with a note saying why.
  using S = IterativeSettings;
  std::vector<std::string> notes;
  auto note = [&notes](const std::string& line) { notes.push_back(line); };
  // A solve that does not converge (two unpreconditioned CG iterations).
  const SparseMatrix a = spd_matrix(200);
  auto s = make_iterative_with_fallback(petsc(S::Krylov::CG, S::Preconditioner::None, 2), SolverKind::Mumps, note);
  s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_TRUE(s->iterative());
  check_solution(a, s->solve(rhs(200)), "CG, then MUMPS");
  EXPECT_FALSE(s->iterative());
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("did not converge"), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("MUMPS factorises the system from now on"), std::string::npos) << notes[0];
  EXPECT_NE(s->name().find("MUMPS (after PETSc CG"), std::string::npos) << s->name();
  // From then on the factorisation serves every matrix.
  const SparseMatrix b = spd_matrix(120);
  s->factorize(b, MatrixKind::SymmetricPositiveDefinite);
  check_solution(b, s->solve(rhs(120)), "MUMPS after the fallback");
  EXPECT_EQ(notes.size(), 1u);
  // A preconditioner that cannot be built (multigrid on a saddle point): MUMPS at once.
  notes.clear();
  const SparseMatrix saddle = saddle_matrix(30);
  auto t = make_iterative_with_fallback(petsc(S::Krylov::CG, S::Preconditioner::Boomer), SolverKind::Mumps, note);
  t->factorize(saddle, MatrixKind::SymmetricIndefinite);
  check_solution(saddle, t->solve(rhs(32)), "saddle point, MUMPS");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("saddle point"), std::string::npos) << notes[0];
  // CG that converges: no fallback.
  notes.clear();
  auto u = make_iterative_with_fallback(petsc(S::Krylov::CG, S::Preconditioner::Jacobi), SolverKind::Mumps, note);
  u->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  check_solution(a, u->solve(rhs(200)), "CG + JACOBI");
  EXPECT_TRUE(u->iterative());
  EXPECT_GT(u->iterations(), 0);
  EXPECT_TRUE(notes.empty());
}

TEST(Solvers, PetscSolveThatMissesItsToleranceFails) {
  using S = IterativeSettings;
  const SparseMatrix a = spd_matrix(200);
  auto s = make_linear_solver(SolverKind::Petsc, petsc(S::Krylov::GMRES, S::Preconditioner::None, 2));
  s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  try {
    s->solve(rhs(200));
    ADD_FAILURE() << "two GMRES iterations reached 1e-13";
  } catch (const SolveError& e) {
    EXPECT_EQ(e.failure().what, Failure::What::IterativeSolve);
    EXPECT_NE(e.message().find("did not converge"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("after 2 iterations"), std::string::npos) << e.message();
  }
}

TEST(Solvers, PetscMultigridOnNodeBlocks) {
  // A 2D elasticity-like system with node blocks (2 components), one component of node 0
  // removed (a Dirichlet condition) and one multiplier-free condensed equation at the end:
  // the layout makes PETSc rebuild 2-blocks with padding rows; the answer is unchanged.
  const int nodes = 30;
  const SparseMatrix base = spd_matrix(2 * nodes);
  std::vector<int> keep;
  for (int eq = 1; eq < 2 * nodes; ++eq) keep.push_back(eq);  // equation 0 (node 0, x) fixed
  std::vector<int> index(2 * nodes, -1);
  for (size_t k = 0; k < keep.size(); ++k) index[keep[k]] = static_cast<int>(k);
  std::vector<Triplet> t;
  for (int c = 0; c < base.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(base, c); it; ++it)
      if (index[it.row()] >= 0 && index[c] >= 0) t.emplace_back(index[it.row()], index[c], it.value());
  const int n = static_cast<int>(keep.size()) + 1;
  t.emplace_back(n - 1, n - 1, 1.0);  // a decoupled (condensed) equation
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  SystemLayout layout;
  layout.dim = 2;
  for (int b = 0; b < nodes; ++b) layout.coords.insert(layout.coords.end(), {0.1 * b, 0.05 * (b % 3)});
  for (int eq : keep) layout.block.push_back(eq / 2), layout.component.push_back(eq % 2);
  layout.block.push_back(-1);
  layout.component.push_back(0);
  using S = IterativeSettings;
  for (S::Preconditioner pc : {S::Preconditioner::Gamg, S::Preconditioner::Boomer, S::Preconditioner::Ml}) {
    auto s = make_linear_solver(SolverKind::Petsc, petsc(S::Krylov::CG, pc));
    s->set_layout(layout);
    s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
    check_solution(a, s->solve(rhs(n)), s->name() + " on node blocks");
    // The operator PETSc multiplies by is the system (for BOOMER, hypre's matrix built from
    // it: the diagonal moved first in each row, the padding rows left out of the product).
    Vector y;
    ASSERT_TRUE(s->multiply(rhs(n), y));
    const Vector ref = a * rhs(n);
    for (int i = 0; i < n; ++i) expect_close(y(i), ref(i), 1e-14, 1e-14, s->name() + " product on node blocks");
  }
}

TEST(Solvers, BoomerStrengthFollowsTheCells) {
  // The strength threshold is 0.7 for a model with quadratic cells and 0.5 otherwise, in the
  // same process (PETSc's options database is shared: the second system must not keep the
  // first one's value); Chebyshev smoothing each way.
  const int n = 60;
  const SparseMatrix a = spd_matrix(n);
  using S = IterativeSettings;
  for (bool quadratic : {true, false, true}) {
    SystemLayout layout;
    layout.dim = 2;
    for (int b = 0; b < n / 2; ++b) layout.coords.insert(layout.coords.end(), {0.1 * b, 0.05 * (b % 3)});
    for (int eq = 0; eq < n; ++eq) layout.block.push_back(eq / 2), layout.component.push_back(eq % 2);
    layout.quadratic = quadratic;
    S settings = petsc(S::Krylov::CG, S::Preconditioner::Boomer);
    std::vector<std::string> lines;
    settings.history = [&lines](const std::string& line) { lines.push_back(line); };
    auto s = make_linear_solver(SolverKind::Petsc, settings);
    s->set_layout(layout);
    s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
    check_solution(a, s->solve(rhs(n)), "BOOMER");
    const std::string expected = std::string("    BoomerAMG: strength threshold ") + (quadratic ? "0.7" : "0.5") +
                                 ", smoothing Chebyshev down, Chebyshev up";
    EXPECT_NE(std::find(lines.begin(), lines.end(), expected), lines.end()) << (lines.empty() ? "" : lines[0]);
  }
}

/// SPD matrix whose equation `dead` has neither stiffness nor coupling.
SparseMatrix singular_zero_column(int n, int dead) {
  std::vector<Triplet> t;
  const SparseMatrix a = spd_matrix(n);
  for (int c = 0; c < a.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(a, c); it; ++it)
      if (it.row() != dead && c != dead) t.emplace_back(it.row(), c, it.value());
  t.emplace_back(dead, dead, 0.0);
  SparseMatrix s(n, n);
  s.setFromTriplets(t.begin(), t.end());
  return s;
}

TEST(Solvers, SingularMatrixReportsFailedColumn) {
  const int dead = 7;
  const SparseMatrix a = singular_zero_column(20, dead);
  for (SolverKind kind : {SolverKind::Cholmod, SolverKind::Umfpack, SolverKind::Mumps}) {
    auto s = make_linear_solver(kind);
    EXPECT_THROW(s->factorize(a, MatrixKind::SymmetricPositiveDefinite), SolveError) << s->name();
    EXPECT_EQ(s->failed_column(), dead) << s->name();
  }
}

/// While alive, every SuiteSparse allocation fails (CHOLMOD and UMFPACK allocate through
/// SuiteSparse_config), as when the factors do not fit in memory.
class SuiteSparseOutOfMemory {
 public:
  SuiteSparseOutOfMemory() : saved_(SuiteSparse_config) {
    SuiteSparse_config.malloc_func = [](size_t) -> void* { return nullptr; };
    SuiteSparse_config.calloc_func = [](size_t, size_t) -> void* { return nullptr; };
    SuiteSparse_config.realloc_func = [](void*, size_t) -> void* { return nullptr; };
  }
  ~SuiteSparseOutOfMemory() { SuiteSparse_config = saved_; }

 private:
  SuiteSparse_config_struct saved_;
};

TEST(Solvers, OutOfMemoryIsNotCalledSingular) {
  const SparseMatrix a = spd_matrix(30);
  for (SolverKind kind : {SolverKind::Cholmod, SolverKind::Umfpack}) {
    auto s = make_linear_solver(kind);
    try {
      SuiteSparseOutOfMemory no_memory;
      s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
      ADD_FAILURE() << s->name() << ": factorised without memory";
    } catch (const SolveError& e) {
      EXPECT_TRUE(e.out_of_memory()) << e.what();
      EXPECT_NE(std::string(e.what()).find("out of memory factorising 30 equations"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find("singular"), std::string::npos) << e.what();
    }
    s->factorize(a, MatrixKind::SymmetricPositiveDefinite);  // memory back: the same solver works
    check_solution(a, s->solve(rhs(30)), s->name() + " after out of memory");
  }
}

// One solver object factorises the matrices of a Newton loop in turn: same pattern with new
// values (MUMPS keeps its analysis), then another pattern and size (it must redo it).
TEST(Solvers, RefactorisationWithNewValuesAndNewPatterns) {
  for (SolverKind kind : {SolverKind::Cholmod, SolverKind::Umfpack, SolverKind::Mumps}) {
    auto s = make_linear_solver(kind);
    SparseMatrix a = spd_matrix(25);
    for (int round = 0; round < 3; ++round) {
      s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
      check_solution(a, s->solve(rhs(25)), s->name() + " round " + std::to_string(round));
      a = a * (2.0 + round);  // same pattern, other values
      a.coeffRef(3, 3) += 1.5 * round;
    }
    const SparseMatrix b = spd_matrix(31);  // other pattern and size
    s->factorize(b, MatrixKind::SymmetricPositiveDefinite);
    check_solution(b, s->solve(rhs(31)), s->name() + " new pattern");
    // Same size and number of entries, one coupling moved: still another pattern.
    std::vector<Triplet> moved;
    for (int col = 0; col < b.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(b, col); it; ++it) {
        const bool pair = (it.row() == 0 && col == 3) || (it.row() == 3 && col == 0);
        moved.emplace_back(pair ? (it.row() == 0 ? 0 : 30) : it.row(), pair ? (col == 0 ? 0 : 30) : col, it.value());
      }
    SparseMatrix b2(31, 31);
    b2.setFromTriplets(moved.begin(), moved.end());
    ASSERT_EQ(b2.nonZeros(), b.nonZeros());
    ASSERT_EQ(b2.coeff(0, 30), -0.5);
    s->factorize(b2, MatrixKind::SymmetricPositiveDefinite);
    check_solution(b2, s->solve(rhs(31)), s->name() + " moved entry, same size");
    if (kind != SolverKind::Cholmod) {
      const SparseMatrix c = saddle_matrix(12);  // other kind
      s->factorize(c, MatrixKind::SymmetricIndefinite);
      check_solution(c, s->solve(rhs(14)), s->name() + " indefinite");
      s->factorize(c * 3.0, MatrixKind::SymmetricIndefinite);
      check_solution(c * 3.0, s->solve(rhs(14)), s->name() + " indefinite, new values");
    }
  }
}

TEST(Solvers, FloatingSpringIsDetectedByCholmod) {
  // Two free springs k(u1-u0)^2, k(u3-u2)^2 with node 0 fixed (by a penalty on u0):
  // equations 2 and 3 float (rigid translation); the failure must be one of them.
  std::vector<Triplet> t = {{0, 0, 2.0}, {0, 1, -1.0}, {1, 0, -1.0}, {1, 1, 1.0},
                            {2, 2, 1.0}, {2, 3, -1.0}, {3, 2, -1.0}, {3, 3, 1.0}};
  SparseMatrix a(4, 4);
  a.setFromTriplets(t.begin(), t.end());
  auto s = make_linear_solver(SolverKind::Cholmod);
  try {
    s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
    FAIL() << "no SolveError";
  } catch (const SolveError& e) {
    EXPECT_TRUE(s->failed_column() == 2 || s->failed_column() == 3) << s->failed_column();
    EXPECT_NE(std::string(e.what()).find("CHOLMOD"), std::string::npos);
  }
}

/// A chain of springs k (equation 0 held by a spring to the ground) whose link between
/// equations 4 and 5 has stiffness `soft` k: equations 5.. hang from the rest by it alone.
SparseMatrix chain_with_soft_link(int n, double soft) {
  std::vector<Triplet> t = {{0, 0, 1.0}};
  for (int i = 0; i + 1 < n; ++i) {
    const double k = i == 4 ? soft : 1.0;
    t.insert(t.end(), {{i, i, k}, {i + 1, i + 1, k}, {i, i + 1, -k}, {i + 1, i, -k}});
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

// SOLVEUR NPREC: a pivot that lost more digits than allowed makes CHOLMOD's factorisation
// singular, with the digits it lost; with more digits allowed, or told to go on
// (STOP_SINGULIER='NON'), the factorisation is kept and solves the system.
TEST(Singularity, CholmodCallsAPivotSingularByTheDigitsItLost) {
  const SparseMatrix a = chain_with_soft_link(10, 1e-9);  // loses about 9 digits at one pivot
  auto s = make_linear_solver(SolverKind::Cholmod);
  s->configure({.singularity = {8, true}});
  try {
    s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
    FAIL() << "a pivot that lost about 9 digits passed a test of 8";
  } catch (const SolveError& e) {
    EXPECT_GE(s->failed_column(), 5) << e.what();  // one of the hanging equations
    EXPECT_GT(e.failure().value, 8.0) << e.what();
    EXPECT_LT(e.failure().value, 10.0) << e.what();
    EXPECT_EQ(e.failure().limit, 8);
    EXPECT_NE(std::string(e.what()).find("significant digits (more than 8)"), std::string::npos) << e.what();
  }
  for (const SingularityTest test : {SingularityTest{10, true}, SingularityTest{-1, true}, SingularityTest{8, false}}) {
    s->configure({.singularity = test});
    s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
    const Vector x = s->solve(rhs(10));
    EXPECT_LT((a * x - rhs(10)).norm() / rhs(10).norm(), 1e-6) << test.digits << (test.stop ? " stop" : " go on");
    if (test.stop) {
      EXPECT_EQ(s->singular_column(), -1);
      EXPECT_TRUE(s->singular_note().empty()) << s->singular_note();
    } else {
      EXPECT_GE(s->singular_column(), 5);
      EXPECT_NE(s->singular_note().find("pivot lost"), std::string::npos) << s->singular_note();
    }
  }
}

// Going on past a pivot CHOLMOD cannot take (zero or negative: for a free body round-off
// decides which): CHOLMOD hands the system to MUMPS, which sets the null pivot aside.
TEST(Singularity, CholmodHandsAPivotItCannotTakeToMumpsWhenToldToGoOn) {
  const int dead = 7;
  const SparseMatrix a = singular_zero_column(20, dead);
  auto s = make_linear_solver(SolverKind::Cholmod);
  EXPECT_THROW(s->factorize(a, MatrixKind::SymmetricPositiveDefinite), SolveError);
  s->configure({.singularity = {8, false}});
  s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(s->singular_column(), dead);
  EXPECT_NE(s->singular_note().find("a pivot CHOLMOD cannot take (zero or negative), so MUMPS factorised the system: "
                                    "1 null pivot(s)"),
            std::string::npos)
      << s->singular_note();
  Vector b = rhs(20);
  b[dead] = 0.0;
  const Vector x = s->solve(b);
  EXPECT_LT((a * x - b).norm() / b.norm(), 1e-12);
  EXPECT_LT(std::abs(x[dead]), 1e-12);
  // A regular matrix afterwards is CHOLMOD's own again.
  const SparseMatrix regular = spd_matrix(20);
  s->factorize(regular, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_TRUE(s->singular_note().empty()) << s->singular_note();
  check_solution(regular, s->solve(rhs(20)), "CHOLMOD after MUMPS");
}

// TYPE_RESOL: MUMPS factorises as asked where the system allows it (an LU of a symmetric
// system, LDL^T with pivoting of a positive definite one) and says which; a factorisation the
// system cannot take (LDL^T without pivoting of an indefinite system, a symmetric one of a
// general system) is the deck's error, not a singular matrix.
TEST(Solvers, MumpsFactorisesAsAskedWhereTheSystemAllowsIt) {
  const SparseMatrix spd = spd_matrix(20);
  const SparseMatrix shift = 3.0 * SparseMatrix(Eigen::VectorXd::Ones(10).asDiagonal());
  const SparseMatrix indefinite = chain_with_soft_link(10, 1.0) - shift;
  struct Case { MatrixKind asked; MatrixKind kind; const SparseMatrix* a; const char* said; };
  for (const Case& c : {Case{MatrixKind::General, MatrixKind::SymmetricPositiveDefinite, &spd, "LU (SYM = 0)"},
                        Case{MatrixKind::SymmetricIndefinite, MatrixKind::SymmetricPositiveDefinite, &spd,
                             "LDL^T with pivoting (SYM = 2)"},
                        Case{MatrixKind::General, MatrixKind::SymmetricIndefinite, &indefinite, "LU (SYM = 0)"}}) {
    auto m = make_linear_solver(SolverKind::Mumps);
    EXPECT_TRUE(m->factorisation_used().empty());
    m->configure({.by_kind = false, .factorisation = c.asked});
    m->factorize(*c.a, c.kind);
    EXPECT_EQ(m->factorisation_used(), c.said);
    const Vector b = rhs(static_cast<int>(c.a->rows()));
    EXPECT_LT((*c.a * m->solve(b) - b).norm() / b.norm(), 1e-12) << c.said;
  }
  auto m = make_linear_solver(SolverKind::Mumps);
  m->configure({.by_kind = false, .factorisation = MatrixKind::SymmetricPositiveDefinite});
  EXPECT_THROW(m->factorize(indefinite, MatrixKind::SymmetricIndefinite), DeckError);
  m->configure({.by_kind = false, .factorisation = MatrixKind::SymmetricIndefinite});
  EXPECT_THROW(m->factorize(spd, MatrixKind::General), DeckError);
  m->configure({});  // by the kind again: said by no one
  m->factorize(spd, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_TRUE(m->factorisation_used().empty());
}

// PRETRAITEMENTS: MUMPS's null-pivot test (NPREC) looks at its scaled matrix, so that a pivot
// near 1e-9 of the matrix's scale is null below 1e-8 in any units (the test above). Without
// preprocessing ('SANS') the pivots are compared as assembled: in units of 2e6 the soft link's
// pivot (4e-3) passes NPREC = 8, and in units of 1e-6 (a pivot of 2e-15) NPREC = 12 stops on it,
// where the scaled test lets it through.
TEST(Singularity, MumpsWithoutPreprocessingTestsPivotsAsAssembled) {
  const SparseMatrix big = chain_with_soft_link(10, 1e-9) * 2e6, small = chain_with_soft_link(10, 1e-9) * 1e-6;
  for (const bool automatic : {true, false}) {
    auto m = make_linear_solver(SolverKind::Mumps);
    m->configure({.preprocessing = automatic, .singularity = {8, true}});
    if (automatic) {
      EXPECT_THROW(m->factorize(big, MatrixKind::SymmetricIndefinite), SolveError);
    } else {
      EXPECT_NO_THROW(m->factorize(big, MatrixKind::SymmetricIndefinite));
      EXPECT_LT((big * m->solve(rhs(10)) - rhs(10)).norm() / rhs(10).norm(), 1e-6);
    }
    m->configure({.preprocessing = automatic, .singularity = {12, true}});
    if (automatic) {
      EXPECT_NO_THROW(m->factorize(small, MatrixKind::SymmetricIndefinite));
    } else {
      EXPECT_THROW(m->factorize(small, MatrixKind::SymmetricIndefinite), SolveError);
    }
  }
}

// MUMPS on a symmetric indefinite system with an equation that nothing holds: a null pivot.
// Stopping (the default) is a SolveError naming it; going on sets it aside (1e20), and the
// solution of a consistent right-hand side is exact on the other equations and zero on it.
TEST(Singularity, MumpsSetsANullPivotAsideWhenToldToGoOn) {
  const int dead = 7;
  const SparseMatrix a = singular_zero_column(20, dead);
  auto s = make_linear_solver(SolverKind::Mumps);
  EXPECT_THROW(s->factorize(a, MatrixKind::SymmetricIndefinite), SolveError);
  EXPECT_EQ(s->failed_column(), dead);
  s->configure({.singularity = {8, false}});
  s->factorize(a, MatrixKind::SymmetricIndefinite);
  EXPECT_EQ(s->singular_column(), dead);
  EXPECT_NE(s->singular_note().find("1 null pivot(s) below 1e-8"), std::string::npos) << s->singular_note();
  Vector b = rhs(20);
  b[dead] = 0.0;  // consistent: nothing loads the free equation
  const Vector x = s->solve(b);
  EXPECT_LT((a * x - b).norm() / b.norm(), 1e-12);
  EXPECT_LT(std::abs(x[dead]), 1e-12);
  // A pivot near 1e-9 of the matrix's scale: null below 1e-8, not below 1e-12, in any units
  // (the threshold applies to MUMPS's scaled matrix).
  for (const double units : {1.0, 2e6, 1e-6}) {
    const SparseMatrix soft = chain_with_soft_link(10, 1e-9) * units;
    auto m = make_linear_solver(SolverKind::Mumps);
    EXPECT_THROW(m->factorize(soft, MatrixKind::SymmetricIndefinite), SolveError) << units;
    m->configure({.singularity = {12, true}});
    m->factorize(soft, MatrixKind::SymmetricIndefinite);
    const Vector y = m->solve(rhs(10));
    EXPECT_LT((soft * y - rhs(10)).norm() / rhs(10).norm(), 1e-6) << units;
  }
}

TEST(Singularity, DescribesNodeAndComponent) {
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  mesh.node_names = {"N1", "N12", "N3"};
  mesh.cell_types = {CellType::Tria3};
  mesh.cell_nodes = {0, 1, 2};
  mesh.cell_offsets = {0, 3};
  mesh.cell_names = {"M1"};
  DofMap dofs(mesh, {0}, 2);
  EXPECT_EQ(dofs.n_dofs(), 6);
  EXPECT_EQ(describe_equation(mesh, dofs, dofs.dof(1, DY)), "node N12, component DY");
  const int lag = dofs.add(1, LAGS_C);
  EXPECT_EQ(lag, 6);
  EXPECT_EQ(dofs.add(1, LAGS_C), 6);
  EXPECT_EQ(describe_equation(mesh, dofs, lag), "node N12, component LAGS_C");
  EXPECT_EQ(describe_equation(mesh, dofs, -1), "equation -1");
  EXPECT_EQ(dofs.node_of(3), 1);
  EXPECT_EQ(dofs.component_of(3), DY);
}

}  // namespace
}  // namespace lunaster::engine

namespace lunaster::engine {
namespace {

/// Stiffness of an n x n (x n) block of QUAD4 (plane strain) or HEXA8 cells, interior nodes
/// moved by up to `distortion` cells, its bottom nodes held by springs `spring`: SPD.
SparseMatrix block_on_springs(CellType type, int n, double distortion, double young, double spring) {
  test::BlockBuilder block(type, n, distortion);
  block.fill();
  const Mesh& mesh = block.mesh();
  const int dim = mesh.dim;
  const FeModel model = test::make_model(mesh, dim, dim == 3 ? Modelisation::Solid3D : Modelisation::PlaneStrain,
                                         ElasticMaterial{young, 0.3, 0.0});
  const DofMap dofs(mesh, model.volume_cells(), dim);
  std::vector<Triplet> t;
  assemble_stiffness(model, dofs, t);
  for (int node = 0; node < mesh.n_nodes(); ++node)
    if (mesh.node(node)[dim - 1] == 0.0)
      for (int c = 0; c < dim; ++c) t.emplace_back(dofs.dof(node, c), dofs.dof(node, c), spring);
  SparseMatrix k(dofs.n_dofs(), dofs.n_dofs());
  k.setFromTriplets(t.begin(), t.end());
  return k;
}

/// A 5-point operator on a side x side grid, coefficients varying along each direction: SPD.
SparseMatrix five_point_operator(int side) {
  const int n = side * side;
  std::vector<Triplet> t;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const int p = i * side + j;
      const double cx = 1.0 + 0.5 * std::sin(0.1 * i), cy = 1.0 + 0.5 * std::cos(0.07 * j);
      t.emplace_back(p, p, 2.0 * (cx + cy) + 1e-3);
      if (j + 1 < side) t.emplace_back(p, p + 1, -cx), t.emplace_back(p + 1, p, -cx);
      if (i + 1 < side) t.emplace_back(p, p + side, -cy), t.emplace_back(p + side, p, -cy);
    }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

/// CHOLMOD's solutions of a x = f for three right-hand sides against UMFPACK's: residual
/// within `residual_tol` of |A| |x| summed, difference within `difference_tol` of the size.
void expect_cholmod_solves_as_umfpack(const SparseMatrix& a, double residual_tol, double difference_tol) {
  auto cholmod = make_linear_solver(SolverKind::Cholmod);
  auto umfpack = make_linear_solver(SolverKind::Umfpack);
  cholmod->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  umfpack->factorize(a, MatrixKind::General);
  const int n = static_cast<int>(a.rows());
  for (int shift = 0; shift < 3; ++shift) {
    Vector f = rhs(n);
    for (int i = 0; i < n; ++i) f[i] *= 1.0 + shift * std::cos(0.3 * i);
    const Vector x = cholmod->solve(f), ref = umfpack->solve(f);
    EXPECT_LT((a * x - f).norm(), residual_tol * (a * x).cwiseAbs().sum()) << "right-hand side " << shift;
    EXPECT_LT((x - ref).norm(), difference_tol * ref.norm()) << "right-hand side " << shift;
  }
}

TEST(Solvers, BackendsAgreeOnAnFeStiffness) {
  // 2D block of 40 x 40 QUAD4 with elastic supports at the bottom: exercises
  // the node-graph ordering and the dense kernels on supernodes of real size.
  const SparseMatrix k = block_on_springs(CellType::Quad4, 40, 0.3, 2.0e6, 1e8);
  const Vector f = rhs(static_cast<int>(k.rows()));
  Vector first;
  for (SolverKind kind : {SolverKind::Cholmod, SolverKind::Umfpack, SolverKind::Mumps}) {
    auto s = make_linear_solver(kind);
    s->factorize(k, MatrixKind::SymmetricPositiveDefinite);
    const Vector x = s->solve(f);
    EXPECT_LT((k * x - f).norm(), 1e-9 * f.norm()) << s->name();
    if (first.size() == 0) first = x;
    else EXPECT_LT((x - first).norm(), 1e-8 * first.norm()) << s->name();
  }
}

TEST(Solvers, CholmodSupernodalSolveAgreesWithUmfpackIn3d) {
  // A 3D HEXA8 block: supernodes of tens of columns with rows below them, so both sweeps of
  // CHOLMOD's supernodal solve (done with Eigen's kernels) meet every case: a supernode with
  // and without rows below, the fill-reducing permutation, several right-hand sides.
  expect_cholmod_solves_as_umfpack(block_on_springs(CellType::Hexa8, 8, 0.2, 2.0e11, 1e13), 1e-12, 1e-9);
}

/// Operations of CHOLMOD's supernodal factor of `a` in the order `perm` (empty: AMD's own).
double factor_operations(const SparseMatrix& a, const std::vector<int>& perm) {
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.supernodal = CHOLMOD_SUPERNODAL;
  common.nmethods = 1;
  common.method[0].ordering = perm.empty() ? CHOLMOD_AMD : CHOLMOD_GIVEN;
  SparseMatrix upper = a.triangularView<Eigen::Upper>();
  upper.makeCompressed();
  cholmod_sparse view = Eigen::viewAsCholmod(upper);
  view.stype = 1;
  std::vector<int> p = perm;
  cholmod_factor* f = cholmod_analyze_p(&view, p.empty() ? nullptr : p.data(), nullptr, 0, &common);
  const double fl = f ? common.fl : -1.0;
  if (f) cholmod_free_factor(&f, &common);
  cholmod_finish(&common);
  return fl;
}

TEST(Solvers, NestedDissectionOfThe3dNodeGraphBeatsMinimumDegree) {
  // METIS on the graph of the nodes of a 16 x 16 x 16 HEXA8 block: a valid order of every
  // equation, and a factor of 3.9e9 operations against AMD's 9.2e9. Ordering the graph of
  // A A^T instead (each node linked to its neighbours' neighbours) gave 8.6e9 here, and more
  // than AMD on the 3D benchmarks.
  const SparseMatrix k = block_on_springs(CellType::Hexa8, 16, 0.2, 2.0e11, 1e13);
  const std::vector<int> nd = given_ordering(k, FactorOrdering::Metis);
  ASSERT_EQ(nd.size(), static_cast<size_t>(k.rows()));
  std::vector<int> sorted = nd;
  std::sort(sorted.begin(), sorted.end());
  for (int j = 0; j < static_cast<int>(sorted.size()); ++j) ASSERT_EQ(sorted[j], j);
  const double with_nd = factor_operations(k, nd), with_amd = factor_operations(k, {});
  ASSERT_GT(with_amd, 0.0);
  EXPECT_LT(with_nd, 0.8 * with_amd) << "nested dissection " << with_nd << ", AMD " << with_amd;
  expect_cholmod_solves_as_umfpack(k, 1e-12, 1e-9);
}

/// The count that `analysis_note()` gives before `what` ("operations", "factor entries").
double count_before(const std::string& note, const std::string& what) {
  const size_t at = note.find(" " + what);
  if (at == std::string::npos) return -1.0;
  const size_t start = note.find_last_of(" ,:;", at - 1);
  return std::stod(note.substr(start + 1, at - start - 1));
}

TEST(Solvers, CholmodSaysWhatItsAnalysisCameTo) {
  // A chain (tridiagonal) without a layout (no node graph: CHOLMOD orders it itself): no
  // fill, 2n - 1 factor entries, and CHOLMOD's count of operations, the sum of the squared
  // column counts of L: 9 columns of 2 entries and the last of 1, 9 x 4 + 1 = 37.
  {
    std::vector<Triplet> t;
    for (int i = 0; i < 10; ++i) {
      t.emplace_back(i, i, 2.0);
      if (i + 1 < 10) t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
    }
    SparseMatrix a(10, 10);
    a.setFromTriplets(t.begin(), t.end());
    auto cholmod = make_linear_solver(SolverKind::Cholmod);
    cholmod->factorize(a, MatrixKind::SymmetricPositiveDefinite);
    const std::string note = cholmod->analysis_note();
    EXPECT_NE(note.find("CHOLMOD's own"), std::string::npos) << note;
    EXPECT_EQ(count_before(note, "factor entries"), 19.0) << note;
    EXPECT_EQ(count_before(note, "operations"), 37.0) << note;
    EXPECT_EQ(note.find("METIS"), std::string::npos) << "a small 1D system tries no nested dissection: " << note;
  }
  // The 16 x 16 x 16 HEXA8 block above: AMD's factor needs over 5e9 operations, so METIS is
  // tried and kept; the note gives its count (as CHOLMOD's analysis of that order counts it)
  // and AMD's, the larger.
  const SparseMatrix k = block_on_springs(CellType::Hexa8, 16, 0.2, 2.0e11, 1e13);
  auto cholmod = make_linear_solver(SolverKind::Cholmod);
  cholmod->factorize(k, MatrixKind::SymmetricPositiveDefinite);
  const std::string note = cholmod->analysis_note();
  ASSERT_EQ(note.find("CHOLMOD analysis, METIS"), 0u) << note;
  const double kept = count_before(note, "operations");
  const double with_nd = factor_operations(k, given_ordering(k, FactorOrdering::Metis));
  EXPECT_NEAR(kept, with_nd, 0.01 * with_nd) << note;
  const size_t amd = note.find("; AMD: ");
  ASSERT_NE(amd, std::string::npos) << note;
  EXPECT_GT(count_before(note.substr(amd), "operations"), kept) << note;
  // Analysed once: new values in the same pattern keep the note.
  SparseMatrix k2 = 2.0 * k;
  cholmod->factorize(k2, MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(cholmod->analysis_note(), note);
}

/// k with its nodes renumbered by a fixed shuffle (each node's `per_node` equations kept
/// together and in order): the same operator, its band spread over the whole matrix.
SparseMatrix shuffled_nodes(const SparseMatrix& k, int per_node) {
  const int nodes = static_cast<int>(k.rows()) / per_node;
  std::vector<int> to(nodes);
  std::iota(to.begin(), to.end(), 0);
  unsigned state = 12345u;
  for (int i = nodes - 1; i > 0; --i) {
    state = state * 1103515245u + 12345u;
    std::swap(to[i], to[(state >> 8) % static_cast<unsigned>(i + 1)]);
  }
  Eigen::VectorXi eq(k.rows());
  for (int v = 0; v < nodes; ++v)
    for (int c = 0; c < per_node; ++c) eq[v * per_node + c] = to[v] * per_node + c;
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p(eq);
  SparseMatrix out;
  out = k.twistedBy(p);
  out.makeCompressed();
  return out;
}

/// Largest distance, in the elimination order perm, between two coupled equations.
int bandwidth_in(const SparseMatrix& a, const std::vector<int>& perm) {
  std::vector<int> position(perm.size());
  for (size_t k = 0; k < perm.size(); ++k) position[perm[k]] = static_cast<int>(k);
  int band = 0;
  for (int j = 0; j < a.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(a, j); it; ++it)
      band = std::max(band, std::abs(position[it.row()] - position[j]));
  return band;
}

void expect_permutation(const std::vector<int>& perm, int n) {
  ASSERT_EQ(perm.size(), static_cast<size_t>(n));
  std::vector<int> sorted = perm;
  std::sort(sorted.begin(), sorted.end());
  for (int j = 0; j < n; ++j) ASSERT_EQ(sorted[j], j);
}

TEST(Solvers, ReverseCuthillMckeeOrdersAShuffledBlockIntoABand) {
  // A 40 x 40 QUAD4 block (41 x 41 nodes, 2 equations a node), its nodes shuffled: in that
  // order coupled equations lie thousands apart. Reverse Cuthill-McKee of the node graph starts
  // at a corner and sweeps the block in L-shaped fronts of at most 81 nodes (162 equations); a
  // coupling joins two consecutive fronts, so it spans at most two of them (163 equations here).
  // Each node's equations stay together.
  const SparseMatrix k = shuffled_nodes(block_on_springs(CellType::Quad4, 40, 0.2, 2.0e6, 1e8), 2);
  const int n = static_cast<int>(k.rows());
  std::vector<int> natural(n);
  std::iota(natural.begin(), natural.end(), 0);
  const std::vector<int> rcm = given_ordering(k, FactorOrdering::Rcm);
  expect_permutation(rcm, n);
  for (int j = 0; j < n; j += 2) EXPECT_EQ(rcm[j + 1], rcm[j] + 1) << "a node's equations split at " << j;
  EXPECT_GT(bandwidth_in(k, natural), n / 2);
  EXPECT_LE(bandwidth_in(k, rcm), 2 * 162);
  // The profile ordering factorises with far less work than no ordering, and with more than AMD.
  const double with_natural = factor_operations(k, natural), with_rcm = factor_operations(k, rcm),
               with_amd = factor_operations(k, given_ordering(k, FactorOrdering::Amd));
  EXPECT_LT(with_rcm, 0.2 * with_natural) << with_rcm << " against " << with_natural;
  EXPECT_LT(with_amd, with_rcm) << with_amd << " against " << with_rcm;
}

TEST(Solvers, ReverseCuthillMckeePlacesEveryComponent) {
  // Two paths, 0-1-2-3 and 4-5-6, and a lone vertex 7: every vertex once; along a path the
  // order runs from one end to the other.
  const std::vector<int> xadj = {0, 1, 3, 5, 6, 7, 9, 10, 10};
  const std::vector<int> adj = {1, 0, 2, 1, 3, 2, 5, 4, 6, 5};
  const std::vector<int> order = reverse_cuthill_mckee(xadj, adj);
  expect_permutation(order, 8);
  std::vector<int> position(8);
  for (int k = 0; k < 8; ++k) position[order[k]] = k;
  for (int v : {0, 1, 2}) EXPECT_EQ(std::abs(position[v + 1] - position[v]), 1) << v;
  for (int v : {4, 5}) EXPECT_EQ(std::abs(position[v + 1] - position[v]), 1) << v;
}


/// The stiffness of a 14 x 14 x 14 HEXA8 block and 225 multipliers, each holding one
/// displacement: a 3D saddle-point system of over 1e4 equations with 3D rows.
SparseMatrix saddle_block() {
  const SparseMatrix k = block_on_springs(CellType::Hexa8, 14, 0.2, 2.0e11, 1e13);
  const int n = static_cast<int>(k.rows()), side = 15;
  std::vector<Triplet> t;
  for (int j = 0; j < k.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(k, j); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  int m = 0;
  for (int node = side * side * (side - 1); node < side * side * side; ++node, ++m) {
    const int held = 3 * node + 2;
    t.emplace_back(n + m, held, 1e11), t.emplace_back(held, n + m, 1e11);
  }
  SparseMatrix a(n + m, n + m);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST(Solvers, MumpsTakesTheOrderingAskedForAndAgreesWithUmfpackIn3d) {
  // MUMPS's LDL^T with each fill-reducing ordering (SOLVEUR RENUM): the ordering MUMPS
  // reports having used (INFOG(7)) is the one asked for, and every solution is UMFPACK's.
  // AUTO on these 3D rows in a process alone: the nested dissection of the node graph.
  const SparseMatrix a = saddle_block();
  auto umfpack = make_linear_solver(SolverKind::Umfpack);
  umfpack->factorize(a, MatrixKind::General);
  const Vector f = rhs(static_cast<int>(a.rows()));
  const Vector ref = umfpack->solve(f);
  const std::pair<FactorOrdering, std::string> cases[] = {
      {FactorOrdering::Auto, "METIS (nested dissection of the node graph), given"},
      {FactorOrdering::Metis, "METIS (nested dissection of the node graph), given"},
      {FactorOrdering::Amd, "AMD"},
      {FactorOrdering::Amf, "AMF"},
      {FactorOrdering::Qamd, "QAMD"},
      {FactorOrdering::Pord, "PORD"},
      {FactorOrdering::Rcm, "reverse Cuthill-McKee, given"},
      {FactorOrdering::Natural, "natural (the equations' own order), given"}};
  for (const auto& [ordering, name] : cases) {
    auto mumps = make_linear_solver(SolverKind::Mumps);
    mumps->configure({.ordering = ordering});
    mumps->factorize(a, MatrixKind::SymmetricIndefinite);
    EXPECT_EQ(mumps->ordering_used(), name);
    const Vector x = mumps->solve(f);
    EXPECT_LT((a * x - f).norm(), 1e-12 * (a * x).cwiseAbs().sum()) << name;
    EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm()) << name;
  }
}

TEST(Solvers, MumpsBlockLowRankCompressesTheFactorsAndRefinementRestoresTheSolve) {
  // ACCELERATION = 'LR' (ICNTL(35) = 1, CNTL(7) = LOW_RANK_SEUIL) on a 3D saddle-point system:
  // the factors keep fewer entries than in full rank, the solve straight from them is off by
  // about the threshold, and iterative refinement on the same factors takes it back to the
  // full-rank solution. In full rank nothing is said; a threshold of 0 keeps every entry.
  const SparseMatrix a = saddle_block();
  const Vector f = rhs(static_cast<int>(a.rows()));
  auto full = make_linear_solver(SolverKind::Mumps);
  full->factorize(a, MatrixKind::SymmetricIndefinite);
  const Vector ref = full->solve(f);
  EXPECT_EQ(full->approximation_note(), "");
  auto entries = [](const std::string& note, const std::string& before) {
    const size_t at = note.find(before);
    return at == std::string::npos ? -1.0 : std::stod(note.substr(at + before.size()));
  };
  auto lossless = make_linear_solver(SolverKind::Mumps);
  lossless->configure({.low_rank = {true, 0.0}});
  lossless->factorize(a, MatrixKind::SymmetricIndefinite);
  const std::string kept_all = lossless->approximation_note();
  EXPECT_EQ(kept_all.rfind("block low-rank factors (threshold 0): ", 0), 0u) << kept_all;
  EXPECT_EQ(entries(kept_all, "): "), entries(kept_all, "against ")) << kept_all;
  EXPECT_LT((lossless->solve(f) - ref).norm(), 1e-12 * ref.norm());

  auto compressed = make_linear_solver(SolverKind::Mumps);
  compressed->configure({.low_rank = {true, 1e-4}});
  compressed->factorize(a, MatrixKind::SymmetricIndefinite);
  const std::string note = compressed->approximation_note();
  const double kept = entries(note, "): "), whole = entries(note, "against ");
  EXPECT_GT(kept, 0.0) << note;
  EXPECT_LT(kept, whole) << note;  // 98 % here: the fronts of 1e4 equations are small for BLR
  const Vector raw = compressed->solve(f);
  EXPECT_GT((raw - ref).norm(), 1e-10 * ref.norm());  // approximate factors
  Vector x;
  const RefinedSolve refined = solve_with_refinement(*compressed, a, f, x, 10, 0.0);
  EXPECT_GE(refined.steps, 1);
  EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm());
}

TEST(Solvers, MumpsFiltersTheMatrixAsCodeAsterDoesAndRefinementRestoresTheSolve) {
  // FILTRAGE_MATRICE: MUMPS factorises the matrix without its entries |a_ij| <= f (|a_ii| +
  // |a_jj|). On the 3D saddle-point system a filter of 1e-4 leaves out 7 % of the entries MUMPS
  // is given (the upper triangle: the note counts them), the solve straight from those factors
  // is off by a relative residual near 1, and refinement against the matrix as assembled takes
  // it to the unfiltered solution (8 steps; 1e-3 leaves out 22 % and 10 steps get to 1e-4). A
  // filter of 1e-30 leaves out nothing (no entry is that small), and without a filter nothing
  // is said.
  const SparseMatrix a = saddle_block();
  const Vector f = rhs(static_cast<int>(a.rows()));
  auto whole = make_linear_solver(SolverKind::Mumps);
  whole->factorize(a, MatrixKind::SymmetricIndefinite);
  const Vector ref = whole->solve(f);
  EXPECT_EQ(whole->approximation_note(), "");
  long long upper = 0;  // MUMPS is given the upper triangle
  for (int c = 0; c < a.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(a, c); it; ++it) upper += it.row() <= c;
  auto counts = [](const std::string& note) {
    long long out = -1, of = -1;
    std::sscanf(note.c_str(), "matrix filtered (%*[^)]): %lld of %lld entries left out", &out, &of);
    return std::pair<long long, long long>{out, of};
  };
  auto nothing = make_linear_solver(SolverKind::Mumps);
  nothing->configure({.filter = 1e-30});
  nothing->factorize(a, MatrixKind::SymmetricIndefinite);
  EXPECT_EQ(nothing->approximation_note(),
            "matrix filtered (1e-30): 0 of " + std::to_string(upper) + " entries left out");
  EXPECT_LT((nothing->solve(f) - ref).norm(), 1e-12 * ref.norm());

  auto filtered = make_linear_solver(SolverKind::Mumps);
  filtered->configure({.filter = 1e-4});
  filtered->factorize(a, MatrixKind::SymmetricIndefinite);
  const std::string note = filtered->approximation_note();
  const auto [out, of] = counts(note);
  EXPECT_EQ(of, upper) << note;
  EXPECT_GT(out, 0) << note;
  EXPECT_LT(out, of / 10) << note;
  const Vector raw = filtered->solve(f);
  EXPECT_GT((raw - ref).norm(), 1e-10 * ref.norm());  // approximate factors
  Vector x;
  const RefinedSolve refined = solve_with_refinement(*filtered, a, f, x, 10, 0.0);
  EXPECT_GE(refined.steps, 1);
  EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm()) << refined.steps << " steps, residual " << refined.residual
                                                 << " from " << refined.raw_residual;
}

TEST(Solvers, PetscLdltSpInBlockLowRankPreconditionsWithCoarserFactors) {
  // LDLT_SP's LOW_RANK_SEUIL: the single-precision factors of the 3D saddle-point system in
  // block low rank. A coarse threshold (1e-2) gives a coarser preconditioner: more Krylov
  // iterations than in full rank, the same solution to the tolerance; the name says so.
  using S = IterativeSettings;
  const SparseMatrix a = saddle_block();
  const Vector f = rhs(static_cast<int>(a.rows()));
  auto full = make_linear_solver(SolverKind::Petsc, petsc(S::Krylov::FGMRES, S::Preconditioner::LdltSp, 200));
  full->factorize(a, MatrixKind::SymmetricIndefinite);
  const Vector ref = full->solve(f);
  IterativeSettings settings = petsc(S::Krylov::FGMRES, S::Preconditioner::LdltSp, 200);
  settings.low_rank = {true, 1e-2};
  settings.workspace_relaxation = 50;
  auto compressed = make_linear_solver(SolverKind::Petsc, settings);
  EXPECT_EQ(compressed->name(), "PETSc FGMRES + single-precision LDL^T in block low rank (threshold 0.01)");
  compressed->factorize(a, MatrixKind::SymmetricIndefinite);
  const Vector x = compressed->solve(f);
  EXPECT_GT(compressed->iterations(), full->iterations());
  EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm());
  EXPECT_LT((a * x - f).norm(), 1e-12 * f.norm());
}

TEST(Solvers, MumpsInSinglePrecisionIsRefinedToTheDoublePrecisionSolution) {
  // MIXER_PRECISION = 'OUI': SMUMPS factorises the 3D saddle-point system in single precision;
  // the solve straight from its factors is off by far more than double precision's round-off,
  // and iterative refinement against the matrix in double precision takes it to the double
  // factorisation's solution.
  const SparseMatrix a = saddle_block();
  const Vector f = rhs(static_cast<int>(a.rows()));
  auto twice = make_mumps_solver(false);
  twice->factorize(a, MatrixKind::SymmetricIndefinite);
  const Vector ref = twice->solve(f);
  auto single = make_mumps_solver(true);
  EXPECT_EQ(single->name(), "MUMPS in single precision");
  single->factorize(a, MatrixKind::SymmetricIndefinite);
  const Vector raw = single->solve(f);
  EXPECT_GT((raw - ref).norm(), 1e-10 * ref.norm());
  EXPECT_LT((raw - ref).norm(), 1e-2 * ref.norm());
  Vector x;
  const RefinedSolve refined = solve_with_refinement(*single, a, f, x, 10, 0.0);
  EXPECT_GE(refined.steps, 1);
  EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm());
  EXPECT_LT((a * x - f).norm(), 1e-12 * (a * x).cwiseAbs().sum());
}

TEST(Solvers, MumpsOutOfCoreAgreesWithInCore) {
  // GESTION_MEMOIRE: the same LDL^T with its factors on disk (ICNTL(22) = 1) solves as in memory,
  // and says where they went; in memory, or left to AUTO with memory to spare, it says nothing.
  const SparseMatrix a = saddle_block();
  const Vector f = rhs(static_cast<int>(a.rows()));
  Vector in_core;
  for (FactorMemory memory : {FactorMemory::InCore, FactorMemory::Auto, FactorMemory::OutOfCore}) {
    auto mumps = make_linear_solver(SolverKind::Mumps);
    mumps->configure({.memory = memory});
    mumps->factorize(a, MatrixKind::SymmetricIndefinite);
    const Vector x = mumps->solve(f);
    if (memory == FactorMemory::OutOfCore) {
      EXPECT_EQ(mumps->memory_used().rfind("out of core, factors in ", 0), 0u) << mumps->memory_used();
      EXPECT_LT((x - in_core).norm(), 1e-12 * in_core.norm());
      // A second factorisation of the same pattern (the analysis kept) writes its factors again.
      mumps->factorize(a, MatrixKind::SymmetricIndefinite);
      EXPECT_LT((mumps->solve(f) - in_core).norm(), 1e-12 * in_core.norm());
    } else {
      EXPECT_EQ(mumps->memory_used(), "");
      if (in_core.size() == 0) in_core = x;
      else EXPECT_LT((x - in_core).norm(), 1e-12 * in_core.norm());
    }
    EXPECT_LT((a * x - f).norm(), 1e-12 * (a * x).cwiseAbs().sum());
  }
}

TEST(Solvers, MumpsAutoGoesOutOfCoreWithinTheRunsMemoryLimit) {
  // GESTION_MEMOIRE='AUTO' with a memory limit that leaves this process 1 MB (less than the
  // in-core estimate): the factors go to disk, the note says why, the solution is the same.
  const SparseMatrix a = saddle_block();
  const Vector f = rhs(static_cast<int>(a.rows()));
  auto in_core = make_linear_solver(SolverKind::Mumps);
  in_core->factorize(a, MatrixKind::SymmetricIndefinite);  // AUTO, no limit: this machine has room
  EXPECT_EQ(in_core->memory_used(), "");
  const Vector ref = in_core->solve(f);
  auto limited = make_linear_solver(SolverKind::Mumps);
  set_memory_budget(resident_bytes() + (std::size_t{1} << 20));
  try {
    limited->factorize(a, MatrixKind::SymmetricIndefinite);
  } catch (...) {
    set_memory_budget(0);
    throw;
  }
  set_memory_budget(0);
  const std::string note = limited->memory_used();
  EXPECT_EQ(note.rfind("out of core, factors in ", 0), 0u) << note;
  EXPECT_NE(note.find(" MB available under the run's memory limit)"), std::string::npos) << note;
  EXPECT_LT((limited->solve(f) - ref).norm(), 1e-12 * ref.norm());
}

TEST(Solvers, MumpsWorkspaceRelaxationIsAllocatedAndSaid) {
  // SOLVEUR PCENT_PIVOT (ICNTL(14)): the factorisation allocates the analysis's estimate plus
  // that percentage, says so, and solves as without it. Not given: MUMPS's default, nothing said.
  const SparseMatrix a = saddle_block();
  const Vector f = rhs(static_cast<int>(a.rows()));
  auto plain = make_linear_solver(SolverKind::Mumps);
  plain->factorize(a, MatrixKind::SymmetricIndefinite);
  EXPECT_EQ(plain->memory_used(), "");
  const Vector ref = plain->solve(f);
  long megabytes[2] = {0, 0};
  const int percents[2] = {20, 400};
  for (int k = 0; k < 2; ++k) {
    auto mumps = make_linear_solver(SolverKind::Mumps);
    mumps->configure({.workspace_relaxation = percents[k]});
    mumps->factorize(a, MatrixKind::SymmetricIndefinite);
    const std::string note = mumps->memory_used();
    const std::string tail = " MB a process (working space: the analysis's estimate + " + std::to_string(percents[k]) + " %)";
    ASSERT_EQ(note.rfind("in memory, ", 0), 0u) << note;
    ASSERT_NE(note.find(tail), std::string::npos) << note;
    megabytes[k] = std::stol(note.substr(11));
    EXPECT_LT((mumps->solve(f) - ref).norm(), 1e-12 * ref.norm());
  }
  // Five times the estimate against 1.2 times it: the allocation grows with it.
  EXPECT_GT(megabytes[1], 2 * megabytes[0]) << megabytes[0] << " MB with 20 %, " << megabytes[1] << " MB with 400 %";
}

TEST(Solvers, CholmodAndUmfpackTakeTheOrderingAskedFor) {
  // SOLVEUR RENUM with MULT_FRONT and LDLT: CHOLMOD (an SPD system) and UMFPACK (an
  // indefinite one) order as asked and say so; every ordering gives the same solution.
  const SparseMatrix k = shuffled_nodes(block_on_springs(CellType::Quad4, 20, 0.2, 2.0e6, 1e8), 2);
  const Vector f = rhs(static_cast<int>(k.rows()));
  auto reference = make_linear_solver(SolverKind::Umfpack);
  reference->factorize(k, MatrixKind::General);
  const Vector ref = reference->solve(f);
  const SparseMatrix s = saddle_block();
  const Vector fs = rhs(static_cast<int>(s.rows()));
  auto mumps = make_linear_solver(SolverKind::Mumps);
  mumps->factorize(s, MatrixKind::SymmetricIndefinite);
  const Vector ref_s = mumps->solve(fs);
  for (FactorOrdering ordering :
       {FactorOrdering::Metis, FactorOrdering::Amd, FactorOrdering::Rcm, FactorOrdering::Natural}) {
    auto cholmod = make_linear_solver(SolverKind::Cholmod);
    cholmod->configure({.ordering = ordering});
    cholmod->factorize(k, MatrixKind::SymmetricPositiveDefinite);
    EXPECT_EQ(cholmod->ordering_used(), ordering_name(ordering));
    const Vector x = cholmod->solve(f);
    EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm()) << ordering_name(ordering);

    auto umfpack = make_linear_solver(SolverKind::Umfpack);
    umfpack->configure({.ordering = ordering});
    umfpack->factorize(s, MatrixKind::SymmetricIndefinite);
    const std::string expected = ordering == FactorOrdering::Amd     ? "AMD or COLAMD"
                                 : ordering == FactorOrdering::Metis ? "METIS (UMFPACK's, on the graph of the equations)"
                                 : ordering == FactorOrdering::Rcm   ? ordering_name(ordering) + ", given"
                                                                     : ordering_name(ordering);
    EXPECT_EQ(umfpack->ordering_used(), expected);
    const Vector y = umfpack->solve(fs);
    EXPECT_LT((s * y - fs).norm(), 1e-12 * (s * y).cwiseAbs().sum()) << ordering_name(ordering);
    EXPECT_LT((y - ref_s).norm(), 1e-9 * ref_s.norm()) << ordering_name(ordering);
  }
}

TEST(Solvers, CholmodSolvesOnTwoThreadsAgreeWithUmfpack) {
  // A 5-point operator on a 300 x 300 grid with varying coefficients: its factor (over 2e6
  // entries) is swept by two threads over disjoint subtrees of the elimination tree, the
  // ancestors they share after (forward) or before (backward). Any update lost or counted
  // twice in that hand-over moves the solution far beyond the tolerance.
  expect_cholmod_solves_as_umfpack(five_point_operator(300), 1e-14, 1e-10);
}

/// The interface solver's answer for K + C (K its reference, C contact terms on the
/// interface's equations) against UMFPACK's factorisation of K + C.
void expect_interface_solves_as_umfpack(SparseMatrix& k, const std::vector<int>& interface, const SparseMatrix& c) {
  auto solver = make_interface_solver(interface);
  ASSERT_TRUE(solver->factorize_reference(k, 0.0));
  solver->factorize(c, MatrixKind::SymmetricIndefinite);
  const SparseMatrix a = k + c;
  auto umfpack = make_linear_solver(SolverKind::Umfpack);
  umfpack->factorize(a, MatrixKind::General);
  const Vector f = rhs(static_cast<int>(a.rows())), x = solver->solve(f), ref = umfpack->solve(f);
  EXPECT_LT((a * x - f).norm(), 1e-12 * f.norm());
  EXPECT_LT((x - ref).norm(), 1e-10 * ref.norm());
}

TEST(InterfaceSolver, SweepsOnTwoThreadsAroundTheSchurComplement) {
  // The 300 x 300 operator with its middle grid row as the interface: a factor large enough
  // for the two-thread sweeps on both sides of the interface's dense Schur complement. The
  // contact terms (a penalty on the row and between neighbours) give K + C, solved directly.
  SparseMatrix k = five_point_operator(300);
  k.makeCompressed();
  const int side = 300, n = side * side;
  std::vector<int> interface;
  for (int j = 0; j < side; ++j) interface.push_back(150 * side + j);
  std::vector<Triplet> t;
  for (int j = 0; j < side; ++j) {
    const int p = interface[j];
    t.emplace_back(p, p, 10.0 + j % 3);
    if (j + 1 < side) t.emplace_back(p, p + 1, -2.0), t.emplace_back(p + 1, p, -2.0);
  }
  SparseMatrix c(n, n);
  c.setFromTriplets(t.begin(), t.end());
  expect_interface_solves_as_umfpack(k, interface, c);
}

/// An elasticity-like operator on a grid of side^dim nodes (dim 2 or 3): the 9- or 27-point
/// stencil (coefficients varying in space) times a 3 x 3 SPD block, three equations per node
/// numbered together: SPD, with the 27 or 81 entries a column of a QUAD4 or HEXA8 mesh's
/// stiffness (three components in 2D too, as a node's equations with a multiplier may be).
SparseMatrix vector_stencil_operator(int side, int dim) {
  const double block[3][3] = {{2.0, 0.3, 0.1}, {0.3, 1.5, -0.2}, {0.1, -0.2, 1.8}};  // SPD
  const int kside = dim == 3 ? side : 1, nodes = side * side * kside;
  std::vector<Triplet> t;
  auto node = [side, kside](int i, int j, int k) { return (i * side + j) * kside + k; };
  const int dk_range = dim == 3 ? 1 : 0;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      for (int k = 0; k < kside; ++k) {
        const int p = node(i, j, k);
        const double c = 1.0 + 0.3 * std::sin(0.4 * i + 0.2 * j + 0.1 * k);
        double diagonal = 1e-2;
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            for (int dk = -dk_range; dk <= dk_range; ++dk) {
              if (di == 0 && dj == 0 && dk == 0) continue;
              const int i2 = i + di, j2 = j + dj, k2 = k + dk;
              diagonal += c;
              if (i2 < 0 || j2 < 0 || k2 < 0 || i2 >= side || j2 >= side || k2 >= kside) continue;
              const int q = node(i2, j2, k2);
              if (q > p)
                for (int a = 0; a < 3; ++a)
                  for (int b = 0; b < 3; ++b) {
                    const double v = -0.5 * c * block[a][b];
                    t.emplace_back(3 * p + a, 3 * q + b, v), t.emplace_back(3 * q + b, 3 * p + a, v);
                  }
            }
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) t.emplace_back(3 * p + a, 3 * p + b, diagonal * block[a][b]);
      }
  SparseMatrix k(3 * nodes, 3 * nodes);
  k.setFromTriplets(t.begin(), t.end());
  k.makeCompressed();
  return k;
}

TEST(InterfaceSolver, OneComponentOfEachInterfaceNode) {
  // The third component of the nodes of the middle row (2D) or plane (3D) is the interface
  // (the normal one of a flat contact surface square to an axis): a node's equations are then
  // partly interior, partly interface. In 2D (27 entries a column) constrained AMD orders the
  // interface last, a node's equations split where the interface begins; in 3D (81) nested
  // dissection orders the interior and the interface is moved last. Contact terms (a penalty
  // coupling each interface equation to its neighbour) give K + C, solved as UMFPACK does.
  for (const auto& [dim, side] : {std::pair{2, 40}, std::pair{3, 12}}) {
    SCOPED_TRACE(dim);
    SparseMatrix k = vector_stencil_operator(side, dim);
    const int n = static_cast<int>(k.rows()), mid = side / 2, kside = dim == 3 ? side : 1;
    std::vector<int> interface;
    for (int j = 0; j < side; ++j)
      for (int l = 0; l < kside; ++l) interface.push_back(3 * ((mid * side + j) * kside + l) + 2);
    std::vector<Triplet> t;
    for (std::size_t q = 0; q < interface.size(); ++q) {
      t.emplace_back(interface[q], interface[q], 30.0 + q % 5);
      if (q + 1 < interface.size())
        t.emplace_back(interface[q], interface[q + 1], -4.0), t.emplace_back(interface[q + 1], interface[q], -4.0);
    }
    SparseMatrix c(n, n);
    c.setFromTriplets(t.begin(), t.end());
    expect_interface_solves_as_umfpack(k, interface, c);
  }
}

TEST(InterfaceSolver, AnInterfaceTooLargeForItsShareOfTheFactorisationIsDeclined) {
  // Every equation of two planes (288) against a small 3D operator: the dense Schur
  // complement (8e6 operations a pass) costs more than the interior's factorisation allows at
  // a share of 1e-3. The reference is then neither factorised nor changed, and the same
  // interface with no limit is factorised.
  const int side = 6;
  SparseMatrix k = vector_stencil_operator(side, 3);
  std::vector<int> interface;
  for (int eq = 0; eq < 2 * 3 * side * side; ++eq) interface.push_back(eq);
  const SparseMatrix before = k;
  auto solver = make_interface_solver(interface);
  EXPECT_FALSE(solver->factorize_reference(k, 1e-3));
  EXPECT_EQ((k - before).norm(), 0.0);
  EXPECT_THROW(solver->factorize(k, MatrixKind::SymmetricIndefinite), InternalError);
  EXPECT_TRUE(solver->factorize_reference(k, 0.0));
  solver->factorize(SparseMatrix(k.rows(), k.cols()), MatrixKind::SymmetricPositiveDefinite);
  const Vector f = rhs(static_cast<int>(k.rows()));
  EXPECT_LT((k * solver->solve(f) - f).norm(), 1e-12 * f.norm());
}

/// A solver that factorises A + shift * diag(A) instead of A: each solve is off by a
/// relative error of about `shift`, as a direct solver is on an ill-conditioned system.
class InexactSolver final : public LinearSolver {
 public:
  explicit InexactSolver(double shift) : shift_(shift) {}
  void factorize(const SparseMatrix& a, MatrixKind kind) override {
    SparseMatrix perturbed = a;
    for (int i = 0; i < a.rows(); ++i) perturbed.coeffRef(i, i) *= 1.0 + shift_;
    inner_->factorize(perturbed, kind);
  }
  Vector solve(const Vector& b) const override { return inner_->solve(b); }
  std::string name() const override { return "inexact CHOLMOD"; }

 private:
  double shift_;
  std::unique_ptr<LinearSolver> inner_ = make_linear_solver(SolverKind::Cholmod);
};

/// A solver whose answer is unrelated to the system: refinement cannot help.
class UselessSolver final : public LinearSolver {
 public:
  void factorize(const SparseMatrix& /*a*/, MatrixKind /*kind*/) override {}
  Vector solve(const Vector& b) const override { return Vector::Constant(b.size(), 1e3); }
  std::string name() const override { return "useless"; }
};

/// CHOLMOD's solution with an error set here, not left to the round-off of one machine and
/// compiler (an exact x made A x - b exactly zero in a -O1 build).
class PerturbedCholmod final : public LinearSolver {
 public:
  explicit PerturbedCholmod(std::function<void(Vector&)> perturb) : perturb_(std::move(perturb)) {}
  void factorize(const SparseMatrix& a, MatrixKind kind) override { inner_->factorize(a, kind); }
  Vector solve(const Vector& b) const override {
    Vector x = inner_->solve(b);
    perturb_(x);
    return x;
  }
  std::string name() const override { return "perturbed CHOLMOD"; }

 private:
  std::function<void(Vector&)> perturb_;
  std::unique_ptr<LinearSolver> inner_ = make_linear_solver(SolverKind::Cholmod);
};

/// A backward-stable solve: x moved by `eps` times its size along (1, ..., 1).
std::function<void(Vector&)> shifted_by(double eps) {
  return [eps](Vector& x) { x.array() += eps * x.cwiseAbs().maxCoeff(); };
}

/// Rows 0 and 1: [1, 1 - 1e-8; 1 - 1e-8, 1] (eigenvalues 2 and 1e-8); the others: identity.
SparseMatrix nearly_singular_pair(int n) {
  SparseMatrix a(n, n);
  for (int i = 0; i < n; ++i) a.insert(i, i) = 1.0;
  a.insert(0, 1) = 1.0 - 1e-8;
  a.insert(1, 0) = 1.0 - 1e-8;
  a.makeCompressed();
  return a;
}
MatrixProduct product_of(const SparseMatrix& a) {
  return [&a](const Vector& x) -> Vector { return a * x; };
}
/// |A| |x|, entry by entry.
MatrixProduct abs_product_of(const SparseMatrix& a) {
  return [&a](const Vector& x) -> Vector {
    Vector y = Vector::Zero(x.size());
    add_abs_product(a, x, y);
    return y;
  };
}

TEST(Refinement, ABackwardStableSolveIsNotRefined) {
  // b along A's smallest eigenvector (eigenvalue 1e-8): x = (1e8, -1e8) and A x cancels to
  // b = (1, -1). An error of 4 eps |x| along the largest eigenvector (eigenvalue 2) leaves
  // a relative residual of about 8e-8 |x| eps / |b| = 8e-8, while the backward error
  // |A x - b| / (|A| |x| + |b|) stays about 4e-16.
  const SparseMatrix a = nearly_singular_pair(2);
  Vector b(2);
  b << 1.0, -1.0;
  const MatrixProduct product = product_of(a), abs_product = abs_product_of(a);
  PerturbedCholmod s(shifted_by(4e-16));
  s.factorize(a, MatrixKind::SymmetricPositiveDefinite);
  Vector x_plain, x_backward;
  const RefinedSolve plain = solve_with_refinement(s, product, b, x_plain);
  const RefinedSolve backward = solve_with_refinement(s, product, b, x_backward, 3, 1e-10, &abs_product);
  EXPECT_GT(backward.raw_residual, 1e-10);  // the relative residual alone asks for refinement
  EXPECT_GE(plain.steps, 1);                // ... and gets a useless step
  EXPECT_EQ(backward.steps, 0);
  EXPECT_NEAR(x_backward[0], 1e8, 1e8 * 1e-7);
  // An inexact factorisation is still refined when the backward error is known.
  const SparseMatrix big = spd_matrix(40);
  InexactSolver inexact(1e-6);
  inexact.factorize(big, MatrixKind::SymmetricPositiveDefinite);
  const MatrixProduct big_product = product_of(big), big_abs = abs_product_of(big);
  Vector x;
  const RefinedSolve refined = solve_with_refinement(inexact, big_product, rhs(40), x, 3, 1e-10, &big_abs);
  EXPECT_GT(refined.steps, 0);
  EXPECT_LT(refined.residual, 1e-10);
  // A backward-stable solve whose residual the caller would reject is still refined.
  Vector x_rejected;
  const RefinedSolve rejected = solve_with_refinement(s, product, b, x_rejected, 3, 1e-10, &abs_product, 1e-12);
  EXPECT_EQ(rejected.steps, plain.steps);
}

TEST(Refinement, ARowFarFromItsOwnRoundOffIsRefined) {
  // Rows 0 and 1 as in ABackwardStableSolveIsNotRefined (terms of 1e8 cancelling to b = 1),
  // row 2 alone: x2 = 1, solved with an error of 1e-9. Against the largest row's terms that
  // error is round-off (1e-9 <= 1e-14 * 2e8); against row 2's own (|A| |x| + |b| = 2) it is
  // not, and x2 is what a contact multiplier would be. Refinement takes it to round-off.
  const SparseMatrix a = nearly_singular_pair(3);
  Vector b(3);
  b << 1.0, -1.0, 1.0;
  const MatrixProduct product = product_of(a), abs_product = abs_product_of(a);
  PerturbedCholmod s([](Vector& x) { x[x.size() - 1] *= 1.0 + 1e-9; });
  s.factorize(a, MatrixKind::SymmetricPositiveDefinite);
  Vector x;
  const RefinedSolve refined = solve_with_refinement(s, product, b, x, 3, 1e-10, &abs_product);
  EXPECT_GT(refined.raw_residual, 1e-10);
  EXPECT_GE(refined.steps, 1);
  EXPECT_NEAR(x[2], 1.0, 1e-15);
}

TEST(Solvers, LargeFactorsOnHugePagesSolveAsSmallOnes) {
  // A 5-point Laplacian on a 250 x 250 grid: CHOLMOD's factor and workspace are blocks of
  // over 4 MB, which the solver libraries' allocator places on huge pages (engine/solver/
  // blas.cpp). UMFPACK's blocks go the same way.
  const SparseMatrix a = five_point_operator(250);
  const Vector b = rhs(static_cast<int>(a.rows()));
  for (const SolverKind kind : {SolverKind::Cholmod, SolverKind::Umfpack}) {
    auto s = make_linear_solver(kind);
    s->factorize(a, kind == SolverKind::Cholmod ? MatrixKind::SymmetricPositiveDefinite : MatrixKind::General);
    const Vector x = s->solve(b);
    EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm()) << s->name();
  }
}

TEST(SymmetricProduct, GathersWhatTheGeneralProductScatters) {
  // A banded symmetric matrix with unequal entries, below and above the 2e5 entries at
  // which the columns are shared between two threads (an uneven split: the band is cut at
  // the ends); the gather must equal Eigen's scatter to round-off and leave no entry unset.
  for (const int n : {500, 30000}) {
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
      for (int j = std::max(0, i - 4); j <= std::min(n - 1, i + 4); ++j)
        t.emplace_back(i, j, 1.0 + 0.01 * ((i + j) % 17) + (i == j ? 10.0 : 0.0));
    SparseMatrix a(n, n);
    a.setFromTriplets(t.begin(), t.end());
    a.makeCompressed();
    ASSERT_EQ(n > 1000, a.nonZeros() >= 200000);
    Vector x(n);
    for (int i = 0; i < n; ++i) x[i] = std::sin(0.37 * i) + 0.5;
    const Vector expected = a * x;
    const Vector y = symmetric_times(a, x);
    ASSERT_EQ(y.size(), n);
    EXPECT_LT((y - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff()) << "n = " << n;
  }
}

TEST(Refinement, AnExactFactorisationNeedsNoRefinement) {
  const SparseMatrix a = spd_matrix(40);
  auto s = make_linear_solver(SolverKind::Cholmod);
  s->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  Vector x;
  const RefinedSolve r = solve_with_refinement(*s, a, rhs(40), x);
  EXPECT_EQ(r.steps, 0);
  EXPECT_LT(r.raw_residual, 1e-14);
  EXPECT_EQ(r.residual, r.raw_residual);
  check_solution(a, x, "CHOLMOD");
}

TEST(Refinement, AnInexactFactorisationIsRefinedToWorkingAccuracy) {
  const SparseMatrix a = spd_matrix(40);
  InexactSolver s(1e-5);
  s.factorize(a, MatrixKind::SymmetricPositiveDefinite);
  Vector x;
  const RefinedSolve r = solve_with_refinement(s, a, rhs(40), x);
  EXPECT_GT(r.raw_residual, 1e-6);  // alone, the solve would miss the driver's 1e-6 bar
  EXPECT_LT(r.residual, 1e-10);     // each step gains about five digits
  EXPECT_EQ(r.steps, 2);
  check_solution(a, x, "refined");
  // With fewer steps allowed, the residual reached is reported as it is.
  Vector y;
  const RefinedSolve one = solve_with_refinement(s, a, rhs(40), y, 1);
  EXPECT_EQ(one.steps, 1);
  EXPECT_GT(one.residual, r.residual);
  EXPECT_LT(one.residual, one.raw_residual);
}

TEST(Refinement, AFixedCountTakesEveryStepAndKeepsTheBestIterate) {
  // code_aster's MINI (ICNTL(10) = -2): two steps whatever they gain. On an exact factorisation
  // the steps gain nothing (or round-off), yet both are taken, and the result is never worse.
  const SparseMatrix a = spd_matrix(40);
  const MatrixProduct product = [&a](const Vector& v) -> Vector { return a * v; };
  auto exact = make_linear_solver(SolverKind::Cholmod);
  exact->factorize(a, MatrixKind::SymmetricPositiveDefinite);
  Vector x;
  const RefinedSolve r = solve_with_refinement(*exact, product, rhs(40), x, 2, 0.0, nullptr, 1e-6, nullptr, true);
  EXPECT_EQ(r.steps, 2);
  EXPECT_LE(r.residual, r.raw_residual);
  // The residual of the kept iterate, through the same product the refinement used (the
  // test's own lambda): the same numbers, so the same residual to the last bit.
  EXPECT_NEAR(relative_residual(product, x, rhs(40)), r.residual, 1e-18);
  // The useless solver's iterates are 1000, 0, -1000: both steps taken, the middle one kept.
  UselessSolver useless;
  useless.factorize(a, MatrixKind::SymmetricPositiveDefinite);
  Vector y;
  const RefinedSolve u = solve_with_refinement(useless, product, rhs(40), y, 2, 0.0, nullptr, 1e-6, nullptr, true);
  EXPECT_EQ(u.steps, 2);
  EXPECT_NEAR(u.residual, 1.0, 1e-15);
  EXPECT_EQ(y, Vector::Zero(40));
}

TEST(Refinement, AUselessSolveIsNeverMadeWorseAndStaysVisiblyWrong) {
  const SparseMatrix a = spd_matrix(40);
  UselessSolver s;
  s.factorize(a, MatrixKind::SymmetricPositiveDefinite);
  Vector x;
  const RefinedSolve r = solve_with_refinement(s, a, rhs(40), x);
  // x = 1000 (residual 1.4e3), then x - 1000 = 0 (residual 1: better, kept), then -1000
  // (worse: refused, stop). The caller sees a residual of 1 and rejects the solve.
  EXPECT_EQ(r.steps, 2);
  EXPECT_GT(r.raw_residual, 1e3);
  EXPECT_NEAR(r.residual, 1.0, 1e-15);
  EXPECT_NEAR(relative_residual(a, x, rhs(40)), r.residual, 1e-15);
  EXPECT_EQ(x, Vector::Zero(40));
}

}  // namespace
}  // namespace lunaster::engine
