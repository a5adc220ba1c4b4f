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

#include "engine/assembly/assembly.hpp"
#include "engine/core/log.hpp"
#include "engine/nonlinear/linear_solve.hpp"
#include "engine/nonlinear/static_solver.hpp"
#include "tests/unit/fe/fe_test_util.hpp"
#include "tests/unit/nonlinear/solver_choice.hpp"

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

/// An unsymmetric spring at one node, seen by the driver as a contact law whose tangent is not
/// symmetric (as a frictional one's in slip): r_x += k u_x + c u_y, r_y += k u_y.
class SkewSpring final : public ContactHook {
 public:
  SkewSpring(int node, double k, double c) : node_(node), k_(k), c_(c) {}
  void add_dofs(DofMap& dofs) override { ex_ = dofs.dof(node_, DX), ey_ = dofs.dof(node_, DY); }
  void begin_step(const Vector&, const Log&) override {}
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override {
    residual[ex_] += k_ * u[ex_] + c_ * u[ey_];
    residual[ey_] += k_ * u[ey_];
    tangent.emplace_back(ex_, ex_, k_);
    tangent.emplace_back(ex_, ey_, c_);
    tangent.emplace_back(ey_, ey_, k_);
  }
  std::vector<int> surface_equations() const override { return {ex_, ey_}; }
  bool settle(const Vector&, const Log&) override { return true; }
  MatrixKind matrix_kind() const override { return MatrixKind::General; }
  int n_active() const override { return 1; }
  void write_fields(const Vector&, ResultStep&) const override {}

 private:
  int node_, ex_ = -1, ey_ = -1;
  double k_, c_;
};

TEST(UnsymmetricSolve, TheDriverSolvesAnUnsymmetricContactTangentWhole) {
  // A 6 x 6 QUAD4 block held on x = 0, a unit force along y at its top right corner, the skew
  // spring there: the driver's answer is an independent sparse LU's of K + S on the free
  // unknowns, with the automatic choice (which would otherwise solve the contact equations by
  // the symmetric Schur complement on the kept elastic factorisation) and with MUMPS.
  constexpr int n = 6;
  test::BlockBuilder block(CellType::Quad4, n, 0.2);
  block.fill();
  const FeModel model = test::make_model(block.mesh(), 2, Modelisation::PlaneStrain, ElasticMaterial{1.0, 0.3, 0.0});
  const int corner = block.vertex(n, n);
  MechanicalLoads loads;
  for (int j = 0; j <= n; ++j)
    for (int cmp : {DX, DY}) loads.dirichlet.push_back({block.vertex(0, j), cmp, 0.0, 0});
  loads.forces.push_back({corner, DY, 1.0, 0});
  loads.multipliers.push_back([](double t) { return t; });
  const double k = 0.5, c = 2.0;

  const DofMap dofs(block.mesh(), model.volume_cells(), 2);
  SparseMatrix whole = assemble_stiffness_matrix(model, dofs);
  std::vector<int> free_index(dofs.n_dofs(), 0);
  for (const DirichletValue& d : loads.dirichlet) free_index[dofs.dof(d.node, d.component)] = -1;
  int n_free = 0;
  for (int& f : free_index)
    if (f == 0) f = n_free++;
  std::vector<Triplet> entries{{free_index[dofs.dof(corner, DX)], free_index[dofs.dof(corner, DX)], k},
                               {free_index[dofs.dof(corner, DX)], free_index[dofs.dof(corner, DY)], c},
                               {free_index[dofs.dof(corner, DY)], free_index[dofs.dof(corner, DY)], k}};
  for (int col = 0; col < whole.outerSize(); ++col)
    for (SparseMatrix::InnerIterator e(whole, col); e; ++e)
      if (free_index[e.row()] >= 0 && free_index[col] >= 0)
        entries.emplace_back(free_index[e.row()], free_index[col], e.value());
  SparseMatrix a(n_free, n_free);
  a.setFromTriplets(entries.begin(), entries.end());
  Vector f = Vector::Zero(n_free);
  f[free_index[dofs.dof(corner, DY)]] = 1.0;
  Eigen::SparseLU<SparseMatrix> lu(a);
  const Vector reference = lu.solve(f);
  const double ux = reference[free_index[dofs.dof(corner, DX)]], uy = reference[free_index[dofs.dof(corner, DY)]];

  for (const bool automatic : {true, false}) {
    SCOPED_TRACE(automatic ? "METHODE AUTO" : "MUMPS");
    NewtonOptions options = test::auto_or_mumps(automatic);
    SkewSpring spring(corner, k, c);
    std::ostringstream sink;
    Log log(sink, 1);
    StaticSolver solver(model, loads, options, &spring, log);
    const std::vector<ResultStep> steps = solver.run({0.0, 1.0});
    const NodalField& depl = steps.back().nodal.at("DEPL");
    test::expect_close(depl.value(corner, 0), ux, 1e-10, 0.0, "u_x at the corner");
    test::expect_close(depl.value(corner, 1), uy, 1e-10, 0.0, "u_y at the corner");
    EXPECT_EQ(solver.stats().interface_equations, 0) << sink.str();
    EXPECT_EQ(sink.str().find("Schur"), std::string::npos) << sink.str();
  }
}

}  // namespace
}  // namespace lunaster::engine
