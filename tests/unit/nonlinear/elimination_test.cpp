// The driver's elimination of unknowns by linear relations (ContactHook::eliminations):
// two blocks with matching interface nodes tied node to node by eliminating the upper
// block's interface displacements give the glued solution, with CHOLMOD (the reduced
// system Q^T K Q is SPD) and one factorisation.
#include <gtest/gtest.h>

#include <sstream>

#include "../contact/two_blocks.hpp"

namespace {

using namespace contact_test;

/// Ties each upper interface node to the lower node at the same place: du_up = du_low + (u_low - u_up).
class TieHook final : public ContactHook {
 public:
  TieHook(const TwoBlocks& tb) {
    for (int up : nodes_of(tb, tb.ab))
      for (int low : nodes_of(tb, tb.ef)) {
        const double* a = tb.mesh.node(up);
        const double* b = tb.mesh.node(low);
        if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) < 1e-12) pairs_.emplace_back(up, low);
      }
  }
  static std::vector<int> nodes_of(const TwoBlocks& tb, const std::vector<int>& cells) {
    std::vector<int> nodes;
    for (int c : cells)
      for (int a = 0; a < tb.mesh.cell_n_nodes(c); ++a) nodes.push_back(tb.mesh.cell(c)[a]);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
  }
  void add_dofs(DofMap& dofs) override { dofs_ = dofs; }
  void begin_step(const Vector&, const lunaster::Log&) override {}
  void add_to_system(const Vector& u, std::vector<Triplet>&, Vector& residual) override {
    // The tie's reaction: the pair is in equilibrium when r_up + r_low = 0.
    for (const auto& [up, low] : pairs_)
      for (int k = 0; k < 2; ++k) {
        residual[dofs_.dof(low, k)] += residual[dofs_.dof(up, k)];
        residual[dofs_.dof(up, k)] = 0.0;
      }
    relations_.clear();
    for (const auto& [up, low] : pairs_)
      for (int k = 0; k < 2; ++k) {
        Elimination e;
        e.eq = dofs_.dof(up, k);
        e.terms = {{dofs_.dof(low, k), 1.0}};
        e.value = u[dofs_.dof(low, k)] - u[dofs_.dof(up, k)];
        relations_.push_back(e);
      }
  }
  const std::vector<Elimination>& eliminations() const override { return relations_; }
  bool settle(const Vector&, const lunaster::Log&) override { return true; }
  MatrixKind matrix_kind() const override { return MatrixKind::SymmetricPositiveDefinite; }
  int n_active() const override { return static_cast<int>(pairs_.size()); }
  void write_fields(const Vector&, ResultStep&) const override {}
  size_t n_pairs() const { return pairs_.size(); }

 private:
  std::vector<std::pair<int, int>> pairs_;
  std::vector<Elimination> relations_;
  DofMap dofs_;
};

TEST(Elimination, TiedInterfaceGivesTheGluedSolutionWithCholesky) {
  const TwoBlocks tb = make_two_blocks(12, 12, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  TieHook hook(tb);
  ASSERT_EQ(hook.n_pairs(), 13u);
  std::ostringstream out;
  lunaster::Log log(out, 1);
  MechanicalLoads loads;
  loads.multipliers.push_back([](double t) { return t; });
  for (const auto& d : displacement_bcs(tb)) loads.dirichlet.push_back({d.node, d.component, d.value, 0});
  NewtonOptions options;
  options.resi_glob_rela = 1e-10;
  options.solver = SolverKind::Cholmod;
  StaticSolver solver(model, loads, options, &hook, log);
  const std::vector<ResultStep> steps = solver.run({0.0, 1.0});
  const NodalField& depl = steps.back().nodal.at("DEPL");
  const int dy = depl.component_index("DY");
  // Uniform strain -0.05 in both blocks: DY = 0.05 (y - 1) above, 0.05 (y + 1) - 0.1... i.e. -0.05 at y = 0.
  double worst = 0.0;
  for (int n = 0; n < tb.mesh.n_nodes(); ++n) {
    const double y = tb.mesh.node(n)[1];
    const double exact = -0.05 * (1.0 + y);  // both blocks: -0.1 at y = 1, 0 at y = -1
    worst = std::max(worst, std::abs(depl.value(n, dy) - exact));
  }
  EXPECT_LT(worst, 1e-13);
  EXPECT_EQ(solver.stats().factorisations, 1);
  EXPECT_EQ(out.str().find("MUMPS"), std::string::npos) << out.str();
}

}  // namespace
