// Mortar contact at slave nodes that also carry an imposed displacement component: the
// interface end points of a quarter ring on its symmetry lines (DY = 0 on y = 0, DX = 0 on
// x = 0). The nodal normal there is the end cell's, tilted from the free direction, so the
// contact force has a component along the imposed one that the support reaction takes; the
// nodal pressure must come from the free components alone, or Newton stalls on a residual
// the eliminated system cannot see.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/contact/mortar_problem.hpp"
#include "ring_sleeve.hpp"

namespace {

using namespace contact_test;
using lunaster::engine::contact::MortarProblem;

/// Pressurised ring (a = 0.5, b = 0.75) in a sleeve (c = 1), plane strain, both fitted:
/// the contact pressure of the Lame solution for p = 1e8 Pa, E 2e11 / 1e11, nu 0.3 / 0.25
/// (testcases/ring_sleeve_mortar.lua derives it).
constexpr double kP = 1.0e8, kQ = 15660243.99987708;

TEST(MortarSymmetry, SlaveEndNodesOnSymmetryLinesConvergeToTheLamePressure) {
  RingSleeve scene;  // matching (12 arcs each): the end nodes are in contact
  make_ring_sleeve_scene(scene, "quad4:12x2", "quad4:12x2", kP);
  const Mesh& mesh = scene.mesh;
  MortarProblem hook(scene.contact, mesh, 2);
  NewtonOptions options;
  options.resi_glob_rela = 1e-8;
  options.iter_glob_maxi = 10;
  options.solver = SolverKind::Cholmod;
  std::ostringstream out;
  lunaster::Log log(out, 1);
  StaticSolver solver(scene.model, scene.loads, options, &hook, log);
  std::vector<ResultStep> steps;
  ASSERT_NO_THROW(steps = solver.run({0.0, 1.0})) << out.str();
  EXPECT_LE(solver.stats().newton_iterations, 3) << out.str();

  const NodalField& depl = steps.back().nodal.at("DEPL");
  const int lags = depl.component_index("LAGS_C");
  ASSERT_EQ(hook.rows().size(), 13u);
  double worst = 0.0;
  for (const auto& row : hook.rows()) {
    EXPECT_TRUE(row.active);
    worst = std::max(worst, std::abs(-depl.value(row.node, lags) - kQ) / kQ);
  }
  // Matching polygonal interface, 12 x 2 cells per body: the discretisation error of the
  // mesh, 7.0e-3 at worst (measured), 4.9e-3 at the end nodes, which are no outliers.
  EXPECT_LT(worst, 8e-3);
  for (const char* end : {"P_X", "P_Y"}) {
    const int n = mesh.node_groups.at(end)[0];
    EXPECT_NEAR(-depl.value(n, lags) / kQ, 1.0, 6e-3) << end;
  }
}

}  // namespace
