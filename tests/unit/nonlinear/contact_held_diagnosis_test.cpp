// The diagnosis of a failed solve when contact holds a body that the stiffness alone leaves
// free: the failure is not named a rigid-body mode of that body, since the contact terms of the
// failed system hold it; a body they do not hold is still named, with a hint that contact does
// not hold it either. Through the production driver: two 2 x 2 QUAD4 blocks side by side with
// nodes of their own, LEFT clamped on x = 0, RIGHT held by a toy penalty hook alone (springs
// tying its nodes on x = 2 to LEFT's there), a force on RIGHT's far edge.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/log.hpp"
#include "engine/nonlinear/static_solver.hpp"
#include "tests/unit/fe/fe_test_util.hpp"

namespace lunaster::engine {
namespace contact_held_test {

constexpr int kBlockCells = 2;

/// Springs of stiffness k between node pairs, on the components given: a penalty tie that the
/// driver sees as a contact hook whose points are all active.
class PenaltyTie final : public ContactHook {
 public:
  PenaltyTie(std::vector<std::pair<int, int>> pairs, std::vector<int> components, double k)
      : pairs_(std::move(pairs)), components_(std::move(components)), k_(k) {}
  void add_dofs(DofMap& dofs) override {
    for (const auto& [a, b] : pairs_)
      for (int c : components_) eqs_.emplace_back(dofs.dof(a, c), dofs.dof(b, c));
  }
  void begin_step(const Vector&, const Log&) override {}
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override {
    for (const auto& [a, b] : eqs_) {
      const double force = k_ * (u[b] - u[a]);
      residual[b] += force;
      residual[a] -= force;
      tangent.emplace_back(a, a, k_);
      tangent.emplace_back(b, b, k_);
      tangent.emplace_back(a, b, -k_);
      tangent.emplace_back(b, a, -k_);
    }
  }
  std::vector<int> surface_equations() const override {
    std::vector<int> out;
    for (const auto& [a, b] : eqs_) out.push_back(a), out.push_back(b);
    return out;
  }
  bool settle(const Vector&, const Log&) override { return true; }
  MatrixKind matrix_kind() const override { return MatrixKind::SymmetricPositiveDefinite; }
  int n_active() const override { return static_cast<int>(eqs_.size()); }
  void write_fields(const Vector&, ResultStep&) const override {}

 private:
  std::vector<std::pair<int, int>> pairs_;
  std::vector<int> components_;
  double k_;
  std::vector<std::pair<int, int>> eqs_;
};

/// The two blocks: node (i, j) of block b at (2 b + i, j), i, j in 0..kBlockCells.
struct SideBySide {
  Mesh mesh;
  FeModel model;
  MechanicalLoads loads;
  int node(int block, int i, int j) const { return block * (kBlockCells + 1) * (kBlockCells + 1) + j * (kBlockCells + 1) + i; }
  SideBySide() {
    for (int b = 0; b < 2; ++b) {
      for (int j = 0; j <= kBlockCells; ++j)
        for (int i = 0; i <= kBlockCells; ++i)
          mesh.add_node(2.0 * b + 2.0 * i / kBlockCells, 2.0 * j / kBlockCells, 0.0, "N" + std::to_string(node(b, i, j) + 1));
      std::vector<int> cells;
      for (int j = 0; j < kBlockCells; ++j)
        for (int i = 0; i < kBlockCells; ++i)
          cells.push_back(mesh.add_cell(CellType::Quad4, {node(b, i, j), node(b, i + 1, j), node(b, i + 1, j + 1),
                                                          node(b, i, j + 1)}));
      mesh.cell_groups[b == 0 ? "LEFT" : "RIGHT"] = cells;
    }
    mesh.detect_dimension();
    model = test::make_model(mesh, 2, Modelisation::PlaneStrain, ElasticMaterial{1.0, 0.3, 0.0});
    for (int j = 0; j <= kBlockCells; ++j)
      for (int c : {DX, DY}) loads.dirichlet.push_back({node(0, 0, j), c, 0.0, 0});
    for (int j = 0; j <= kBlockCells; ++j) loads.forces.push_back({node(1, kBlockCells, j), DX, 0.1, 0});
    loads.multipliers.push_back([](double t) { return t; });
  }
  /// LEFT's nodes on x = 2 with RIGHT's there, rows `rows`.
  std::vector<std::pair<int, int>> interface(const std::vector<int>& rows) const {
    std::vector<std::pair<int, int>> pairs;
    for (int j : rows) pairs.emplace_back(node(0, kBlockCells, j), node(1, 0, j));
    return pairs;
  }
};

/// The error of a run that failed in a linear solve, and its log.
struct FailedRun {
  bool failed = false;
  Failure::What what = Failure::What::Unspecified;
  std::string message, log;
};

FailedRun run_tied(const SideBySide& scene, PenaltyTie& tie) {
  NewtonOptions options;
  options.auto_solver = false;  // CHOLMOD as named: the whole system, no interface solver
  std::ostringstream sink;
  Log log(sink, 1);
  StaticSolver solver(scene.model, scene.loads, options, &tie, log);
  FailedRun out;
  try {
    solver.run({0.0, 1.0});
  } catch (const SolveError& e) {
    out.failed = true;
    out.what = e.failure().what;
    out.message = e.what();
  }
  out.log = sink.str();
  return out;
}

TEST(ContactHeldDiagnosis, ABodyTheContactHoldsIsNotNamedFree) {
  // Every node pair tied in x and y, 1e13 times stiffer than the blocks: RIGHT is held, but a
  // pivot of the tie loses about 13 digits, more than the 8 allowed, and the factorisation
  // stops. K_ff alone leaves RIGHT free; the failed system's contact terms hold it.
  SideBySide scene;
  PenaltyTie tie(scene.interface({0, 1, 2}), {DX, DY}, 1e13);
  const FailedRun r = run_tied(scene, tie);
  ASSERT_TRUE(r.failed) << r.log;
  EXPECT_EQ(r.what, Failure::What::ContactConditioning) << r.message;
  EXPECT_NE(r.message.find("but the contact terms of the failed system hold that body"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("the body RIGHT (4 cells) has a rigid-body mode"), std::string::npos) << r.message;
  EXPECT_EQ(r.message.find("the stiffness matrix is singular"), std::string::npos) << r.message;
  // The same tie at a stiffness the pivots take: the run converges (RIGHT is held indeed).
  PenaltyTie moderate(scene.interface({0, 1, 2}), {DX, DY}, 10.0);
  const FailedRun ok = run_tied(scene, moderate);
  EXPECT_FALSE(ok.failed) << ok.message;
}

TEST(ContactHeldDiagnosis, ABodyTheContactDoesNotHoldIsStillNamed) {
  // One node pair tied in x only: RIGHT can still move along y (and turn about that node);
  // the system is singular, the rigid-body mode is RIGHT's, and contact does not hold it.
  SideBySide scene;
  PenaltyTie tie(scene.interface({1}), {DX}, 10.0);
  const FailedRun r = run_tied(scene, tie);
  ASSERT_TRUE(r.failed) << r.log;
  EXPECT_EQ(r.what, Failure::What::RigidBodyMode) << r.message;
  EXPECT_NE(r.message.find("the body RIGHT (4 cells) has a rigid-body mode"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("the contact terms of the failed system do not hold it either"), std::string::npos)
      << r.message;
}

}  // namespace contact_held_test
}  // namespace lunaster::engine
