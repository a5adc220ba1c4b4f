// The system mortar contact hands to CHOLMOD, read directly: with the active slave nodes'
// normal components eliminated through D^-1 M (mortar_problem.hpp), the driver factorises
// Q^T K Q, which must be symmetric and positive definite on non-matching interfaces whose
// relations mix components (a curved 2D interface) and couple several master nodes (3D).
// The patch tests check the values; this checks the matrix itself.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "engine/contact/mortar_problem.hpp"
#include "engine/mesh/cell_topology.hpp"
#include "ring_sleeve.hpp"

namespace {

using namespace contact_test;
using lunaster::engine::contact::MortarProblem;
namespace tools = lunaster::tools;

/// What the observer saw of every matrix factorised with active contact.
struct Seen {
  int matrices = 0;           ///< matrices factorised
  int spd_kind = 0;           ///< of which given to the backend as SPD
  double asymmetry = 0.0;     ///< max |a_ij - a_ji| / max |a_ij|, over all of them
  int cholesky_failures = 0;  ///< Eigen's LL^T of the matrix failed (not positive definite)
  long long couplings = 0;    ///< entries coupling a slave-body and a master-body equation
};

/// Observer filling `seen`; `slave_body[node]` flags the nodes of the slave body, `dofs` is
/// the run's numbering (set once the solver exists, before its run).
std::function<void(const SparseMatrix&, MatrixKind, const std::vector<int>&)> observer(
    Seen& seen, const std::vector<char>& slave_body, const DofMap*& dofs) {
  return [&seen, &slave_body, &dofs](const SparseMatrix& a, MatrixKind kind, const std::vector<int>& equation) {
    ++seen.matrices;
    if (kind == MatrixKind::SymmetricPositiveDefinite) ++seen.spd_kind;
    const SparseMatrix at = a.transpose();
    const double scale = a.coeffs().abs().maxCoeff();
    seen.asymmetry = std::max(seen.asymmetry, SparseMatrix(a - at).coeffs().abs().maxCoeff() / scale);
    Eigen::SimplicialLLT<SparseMatrix> llt(a);
    if (llt.info() != Eigen::Success) ++seen.cholesky_failures;
    for (int j = 0; j < a.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(a, j); it; ++it) {
        const int ni = dofs->node_of(equation[it.row()]), nj = dofs->node_of(equation[j]);
        if (it.value() != 0.0 && ni >= 0 && nj >= 0 && slave_body[ni] != slave_body[nj]) ++seen.couplings;
      }
  };
}

/// One step of `hook` on `model` under `loads` through the driver with CHOLMOD, every factorised
/// matrix read by the observer; `slave_body_cells` are the slave body's cells. Returns what it saw.
Seen solve_and_read(const FeModel& model, const MechanicalLoads& loads, const std::vector<int>& slave_body_cells,
                    MortarProblem& hook, std::vector<ResultStep>* steps) {
  const Mesh& mesh = *model.mesh;
  std::vector<char> slave_body(mesh.n_nodes(), 0);
  for (int n : mesh.nodes_of_cells(slave_body_cells)) slave_body[n] = 1;
  Seen seen;
  const DofMap* dofs = nullptr;
  NewtonOptions options;
  options.resi_glob_rela = 1e-8;
  options.solver = SolverKind::Cholmod;
  options.observe_factorisation = observer(seen, slave_body, dofs);
  std::ostringstream out;
  lunaster::Log log(out, 1);
  StaticSolver solver(model, loads, options, &hook, log);
  dofs = &solver.dofs();
  std::vector<ResultStep> result;
  EXPECT_NO_THROW(result = solver.run({0.0, 1.0})) << out.str();
  EXPECT_EQ(out.str().find("MUMPS"), std::string::npos) << out.str();  // CHOLMOD took every system
  if (steps) *steps = std::move(result);
  return seen;
}

/// The observer's verdict: every matrix SPD-kind, symmetric to 1e-14, LL^T-factorisable, and
/// coupling the two bodies (condensed through Q, not solved apart).
void expect_condensed_spd(const Seen& seen) {
  ASSERT_GE(seen.matrices, 1);
  EXPECT_EQ(seen.spd_kind, seen.matrices);
  EXPECT_LE(seen.asymmetry, 1e-14);
  EXPECT_EQ(seen.cholesky_failures, 0);
  EXPECT_GT(seen.couplings, 0);
}

TEST(MortarCondensedSystem, IsSymmetricPositiveDefiniteOnACurvedNonMatchingInterface) {
  // Quarter ring in a sleeve, 12 against 9 arcs: the interface normals turn through 90
  // degrees, so each eliminated relation mixes DX and DY of several master nodes.
  RingSleeve scene;
  make_ring_sleeve_scene(scene, "quad4:12x2", "quad4:9x2", 1e8);
  MortarProblem hook(scene.contact, scene.mesh, 2);
  const Seen seen = solve_and_read(scene.model, scene.loads, scene.mesh.cell_groups.at("RING"), hook, nullptr);
  // The two polygons do not fit (a 9-chord arc lies inside a 12-chord one by up to 2.9e-3 m,
  // ten times the ring's expansion), so contact holds where they cross: the active rows are
  // few, and their normals are tilted (the relations mix DX and DY).
  int active = 0, tilted = 0;
  for (const auto& row : hook.rows())
    if (row.active) ++active, tilted += std::min(std::abs(row.normal[0]), std::abs(row.normal[1])) > 0.1 ? 1 : 0;
  EXPECT_GE(active, 3);
  EXPECT_GE(tilted, 2);
  expect_condensed_spd(seen);
}

TEST(MortarCondensedSystem, IsSymmetricPositiveDefiniteOnANonMatching3dInterface) {
  // PENTA6 block (slave TRIA3 faces of side 1/3) under a HEXA20 block (master QUAD8 faces of
  // side 1/2), Young's moduli 6e6 and 2e6: each slave node's relation couples up to nine
  // master nodes of one or more QUAD8 faces.
  tools::Ssnp121Options3d opt;
  opt.v1 = tools::parse_block_cells("penta6:3x3x1", 3);
  opt.v2 = tools::parse_block_cells("hexa20:2x2x1", 3);
  const Mesh mesh = tools::make_ssnp121_3d(opt);
  FeModel model;
  model.mesh = &mesh;
  model.dim = 3;
  model.modelisation.assign(mesh.n_cells(), Modelisation::None);
  model.material.assign(mesh.n_cells(), -1);
  model.materials.push_back({6e6, 0.0, 0.0});
  model.materials.push_back({2e6, 0.0, 0.0});
  for (int c : mesh.cell_groups.at("V1")) model.modelisation[c] = Modelisation::Solid3D, model.material[c] = 0;
  for (int c : mesh.cell_groups.at("V2")) model.modelisation[c] = Modelisation::Solid3D, model.material[c] = 1;
  ContactDefinition def;
  def.method = ContactMethod::MortarLagrange;
  ContactZone zone;
  zone.slave_cells = mesh.cell_groups.at("SURESC");
  zone.master_cells = mesh.cell_groups.at("SURMAI");
  zone.init = ContactInit::Yes;
  zone.coef_cont = 100.0;
  def.zones.push_back(zone);
  def.modulus = 6e6;
  MortarProblem hook(def, mesh, 3);
  MechanicalLoads loads;
  loads.multipliers.push_back([](double t) { return t; });
  for (int n : mesh.nodes_of_cells(mesh.cell_groups.at("ENCAST")))
    for (int c : {DX, DY, DZ}) loads.dirichlet.push_back({n, c, 0.0, 0});
  for (int n : mesh.nodes_of_cells(mesh.cell_groups.at("SURCHA"))) {
    loads.dirichlet.push_back({n, DX, 0.0, 0});
    loads.dirichlet.push_back({n, DY, 0.0, 0});
    loads.dirichlet.push_back({n, DZ, -0.1, 0});
  }
  std::vector<ResultStep> steps;
  const Seen seen = solve_and_read(model, loads, mesh.cell_groups.at("V1"), hook, &steps);
  int active = 0;
  for (const auto& row : hook.rows()) active += row.active ? 1 : 0;
  EXPECT_EQ(active, 16);  // the 4 x 4 slave nodes
  expect_condensed_spd(seen);
  // And the solve it gave is the springs-in-series state: p = 0.1 / (1/6e6 + 1/2e6).
  ASSERT_FALSE(steps.empty());
  const NodalField& depl = steps.back().nodal.at("DEPL");
  const int lags = depl.component_index("LAGS_C");
  for (const auto& row : hook.rows()) EXPECT_NEAR(depl.value(row.node, lags) / -1.5e5, 1.0, 1e-10);
}

}  // namespace
