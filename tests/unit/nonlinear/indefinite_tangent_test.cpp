// A behaviour whose tangent is not positive definite (a softening law) through the production
// Newton driver: its system is factorised as symmetric indefinite (LU or LDL^T), never by
// Cholesky, which stops at the first negative pivot. The law here is linear in the strain with a
// negative shear modulus (a law softened in shear), declared nonlinear so that the driver takes
// its tangent: the Newton solution is then K_ff^-1 f_F, which a dense LU of the same stiffness,
// assembled apart, gives independently.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "engine/assembly/assembly.hpp"
#include "engine/core/log.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/nonlinear/static_solver.hpp"
#include "tests/unit/fe/fe_test_util.hpp"
#include "tests/unit/nonlinear/solver_choice.hpp"

namespace lunaster::engine {
namespace {

constexpr double kE = 1000.0, kShear = -150.0;

/// sigma = D eps, D = diag(E, E, 0, G) with G < 0 (plane models, 4 entries): indefinite.
class ShearSoftened final : public Behaviour {
 public:
  bool is_linear() const override { return false; }
  bool tangent_positive_definite() const override { return false; }
  const std::vector<std::string>& variable_names() const override { return names_; }
  IntegrationStatus integrate(const PointInput& in, PointOutput& out) const override {
    TangentMatrix d = TangentMatrix::Zero(4, 4);
    d(0, 0) = d(1, 1) = kE;
    d(3, 3) = kShear;
    out.stress = d * in.strain_end;
    if (out.want_tangent) out.tangent = d;
    return IntegrationStatus::Ok;
  }

 private:
  std::vector<std::string> names_;
};

TEST(IndefiniteTangent, ASofteningTangentIsFactorisedIndefiniteAndSolvedExactly) {
  // A 4 x 4 QUAD4 block (distorted interior nodes, plane strain) held on x = 0, forces along x
  // and y on x = 1.
  constexpr int n = 4;
  test::BlockBuilder block(CellType::Quad4, n, 0.2);
  block.fill();
  const FeModel model = test::make_model(block.mesh(), 2, Modelisation::PlaneStrain, ElasticMaterial{kE, 0.0, 0.0});
  CellBehaviours behaviours(model);
  behaviours.assign(model.volume_cells(), std::make_shared<ShearSoftened>());
  MechanicalLoads loads;
  for (int j = 0; j <= n; ++j)
    for (int cmp : {DX, DY}) loads.dirichlet.push_back({block.vertex(0, j), cmp, 0.0, 0});
  for (int j = 0; j <= n; ++j) {
    loads.forces.push_back({block.vertex(n, j), DX, 1.0 + 0.1 * j, 0});
    loads.forces.push_back({block.vertex(n, j), DY, 0.5 - 0.2 * j, 0});
  }
  loads.multipliers.push_back([](double t) { return t; });

  // The reference: the same stiffness assembled apart, restricted to the free unknowns, solved
  // by a dense LU. It has negative eigenvalues (no Cholesky exists) and is regular.
  const DofMap dofs(block.mesh(), model.volume_cells(), 2);
  const SparseMatrix k = assemble_stiffness_matrix(behaviours, dofs);
  std::vector<int> free_index(dofs.n_dofs(), 0);
  for (const DirichletValue& d : loads.dirichlet) free_index[dofs.dof(d.node, d.component)] = -1;
  int n_free = 0;
  for (int& f : free_index)
    if (f == 0) f = n_free++;
  Eigen::MatrixXd k_ff = Eigen::MatrixXd::Zero(n_free, n_free);
  for (int col = 0; col < k.outerSize(); ++col)
    for (SparseMatrix::InnerIterator e(k, col); e; ++e)
      if (free_index[e.row()] >= 0 && free_index[col] >= 0) k_ff(free_index[e.row()], free_index[col]) += e.value();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_free);
  for (const NodalForce& force : loads.forces) f[free_index[dofs.dof(force.node, force.component)]] += force.value;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(k_ff);
  ASSERT_LT(eigen.eigenvalues().minCoeff(), 0.0) << "the stiffness is to be indefinite";
  ASSERT_GT(eigen.eigenvalues().cwiseAbs().minCoeff(), 1e-6 * eigen.eigenvalues().cwiseAbs().maxCoeff())
      << "and regular";
  const Eigen::VectorXd reference = k_ff.fullPivLu().solve(f);

  for (const bool automatic : {true, false}) {
    SCOPED_TRACE(automatic ? "METHODE AUTO" : "MUMPS");
    NewtonOptions options = test::auto_or_mumps(automatic);
    std::vector<MatrixKind> factorised;
    options.observe_factorisation = [&factorised](const SparseMatrix&, MatrixKind kind, const std::vector<int>&) {
      factorised.push_back(kind);
    };
    std::ostringstream sink;
    Log log(sink, 1);
    StaticSolver solver(model, loads, options, nullptr, log);
    solver.set_behaviours(&behaviours);
    std::vector<ResultStep> steps;
    ASSERT_NO_THROW(steps = solver.run({0.0, 1.0})) << sink.str();
    ASSERT_FALSE(factorised.empty());
    for (MatrixKind kind : factorised) EXPECT_EQ(kind, MatrixKind::SymmetricIndefinite) << sink.str();
    // Nor the saddle-point backend, whose Schur form of an indefinite block has no Cholesky.
    if (automatic) EXPECT_NE(sink.str().find("indefinite system; using UMFPACK"), std::string::npos) << sink.str();
    const NodalField& depl = steps.back().nodal.at("DEPL");
    for (int node = 0; node < block.mesh().n_nodes(); ++node)
      for (int cmp : {DX, DY}) {
        const int eq = free_index[dofs.dof(node, cmp)];
        const double expected = eq >= 0 ? reference[eq] : 0.0;
        test::expect_close(depl.value(node, cmp == DX ? 0 : 1), expected, 1e-9, 1e-12 * reference.cwiseAbs().maxCoeff(),
                           "u at node " + std::to_string(node));
      }
  }
}

}  // namespace
}  // namespace lunaster::engine
