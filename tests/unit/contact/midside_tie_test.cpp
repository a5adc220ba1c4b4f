// Discrete contact on QUAD8 faces ties every mid-side node to the mean of its edge's
// vertices (code_aster's CONTACT_8 relations), on the slave and the master face; a
// relation whose three nodes are all imposed by DDL_IMPO in a component is left out.
// The deck testcases/ssnp121d_discrete.lua shows what the ties buy: the patch test on
// the matching HEXA20 mesh of SSNP121 D to round-off.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "engine/assembly/dof_map.hpp"
#include "engine/contact/contact_factory.hpp"
#include "engine/contact/contact_problem.hpp"
#include "engine/io/med_reader.hpp"

namespace {

using namespace lunaster::engine;
using lunaster::engine::contact::ContactProblem;

/// The shared contact part behind a discrete method (node to segment).
std::unique_ptr<ContactHook> hook_for(const ContactDefinition& def, const Mesh& mesh) {
  return make_contact_hook(def, mesh, 3);
}
const ContactProblem& problem(const std::unique_ptr<ContactHook>& hook) {
  return dynamic_cast<const ContactProblem&>(*hook);
}

Mesh load(const std::string& name) {
  return read_med(std::string(LUNASTER_SOURCE_DIR) + "/testcases/" + name + ".med");
}

ContactDefinition discrete(const Mesh& mesh, ContactMethod method) {
  ContactDefinition def;
  def.method = method;
  ContactZone z;
  z.slave_cells = mesh.cell_groups.at("SURMAI");
  z.master_cells = mesh.cell_groups.at("SURESC");
  z.coef_pena = 1.0e12;
  def.zones.push_back(z);
  return def;
}

std::vector<int> volume_cells(const Mesh& mesh) {
  std::vector<int> cells;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.cell_types[c] == CellType::Hexa20) cells.push_back(c);
  return cells;
}

TEST(MidSideTie, EveryQuad8MidSideNodeOfBothFacesIsTiedOnce) {
  const Mesh mesh = load("ssnp121d");  // 4x4 QUAD8 per face: 2 * 4 * 5 = 40 mid-side nodes each
  auto hook = hook_for(discrete(mesh, ContactMethod::DiscretePenalty), mesh);
  const auto& relations = problem(hook).relations().relations();
  ASSERT_EQ(relations.size(), 3 * 80u);  // one relation per mid-side node and component
  std::set<std::pair<int, int>> tied;
  for (const auto& r : relations) {
    ASSERT_EQ(r.terms.size(), 3u);
    const int mid = r.terms[0].node, a = r.terms[1].node, b = r.terms[2].node;
    EXPECT_EQ(r.carrier_node, mid);
    EXPECT_EQ(r.carrier_component, LAGR_DX + r.terms[0].component);
    EXPECT_TRUE(tied.insert({mid, r.terms[0].component}).second) << "node tied twice: " << mesh.node_names[mid];
    for (int i = 0; i < 3; ++i)  // the mid-side node sits halfway along its edge
      EXPECT_NEAR(mesh.node(mid)[i], 0.5 * (mesh.node(a)[i] + mesh.node(b)[i]), 1e-12);
    const double scale = r.terms[0].coef;
    EXPECT_NEAR(scale, 0.25 * 0.25, 1e-12);  // squared edge length of a 4x4 face
    EXPECT_DOUBLE_EQ(r.terms[1].coef, -0.5 * scale);
    EXPECT_DOUBLE_EQ(r.terms[2].coef, -0.5 * scale);
  }
  // The ties are multipliers: even penalty contact then solves a symmetric indefinite system.
  EXPECT_EQ(hook->matrix_kind(), MatrixKind::SymmetricIndefinite);
}

TEST(MidSideTie, RelationsImposedByDirichletConditionsAreLeftOut) {
  const Mesh mesh = load("ssnp121d");
  auto hook = hook_for(discrete(mesh, ContactMethod::DiscreteLagrange), mesh);
  // DX imposed on every node of the slave face SURMAI: its 40 DX relations hold already.
  std::vector<DirichletValue> fixed;
  std::set<int> slave_nodes;
  for (int c : mesh.cell_groups.at("SURMAI"))
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) slave_nodes.insert(mesh.cell(c)[a]);
  for (int n : slave_nodes) fixed.push_back({n, DX, 0.0, 0});
  hook->set_dirichlet(fixed);
  DofMap dofs(mesh, volume_cells(mesh), 3);
  hook->add_dofs(dofs);
  int left_out = 0, kept = 0;
  for (const auto& r : problem(hook).relations().relations()) {
    const int mid = r.terms[0].node, component = r.terms[0].component;
    const bool on_slave = slave_nodes.count(mid) > 0;
    if (component != DX) {
      EXPECT_GE(r.multiplier, 0);
      continue;
    }
    EXPECT_EQ(r.multiplier < 0, on_slave) << mesh.node_names[mid];
    if (r.multiplier >= 0) {
      EXPECT_EQ(dofs.component_of(r.multiplier), LAGR_DX);
    }
    (r.multiplier < 0 ? left_out : kept)++;
  }
  EXPECT_EQ(left_out, 40);
  EXPECT_EQ(kept, 40);
}

TEST(MidSideTie, LinearFacesAreNotTied) {
  const Mesh mesh = load("ssnp121j");  // PENTA6 below (TRIA3 face), PENTA15 above (TRIA6 face)
  ContactDefinition def = discrete(mesh, ContactMethod::DiscretePenalty);
  auto hook = hook_for(def, mesh);
  EXPECT_TRUE(problem(hook).relations().empty());
  EXPECT_EQ(hook->matrix_kind(), MatrixKind::SymmetricPositiveDefinite);
}

TEST(MidSideTie, TheHookHandsOverTheTiesAskedForAndKeepsTheOthers) {
  const Mesh mesh = load("ssnp121d");
  auto hook = hook_for(discrete(mesh, ContactMethod::DiscreteLagrange), mesh);
  const auto taken = hook->take_relations([](const LinearRelation& r) { return r.terms[0].component == DX; });
  EXPECT_EQ(taken.size(), 80u);
  for (const auto& r : taken)
    EXPECT_EQ(r.label.rfind("discrete contact's tie of QUAD8 mid-side node N", 0), 0u) << r.label;
  const auto& kept = problem(hook).relations().relations();
  ASSERT_EQ(kept.size(), 160u);
  for (const auto& r : kept) EXPECT_NE(r.terms[0].component, DX);
  EXPECT_EQ(hook->take_relations().size(), 160u);  // no choice: all that is left
  EXPECT_TRUE(problem(hook).relations().relations().empty());
}

}  // namespace
