// The node names of code_aster's GIBI script of SSNP121 (lunaster-meshgen --gibi-node-names): code_aster's
// SSNP121 decks name node N14, which that script puts in the middle of AB.
#include <gtest/gtest.h>

#include <set>

#include "engine/core/error.hpp"
#include "tools/ssnp121_mesh.hpp"

namespace lunaster {
namespace {

using engine::Mesh;

int node_named(const Mesh& mesh, const std::string& name) {
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (mesh.node_names[n] == name) return n;
  return -1;
}

bool in_group(const Mesh& mesh, const std::string& cells, int node) {
  for (int c : mesh.cell_groups.at(cells))
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a)
      if (mesh.cell(c)[a] == node) return true;
  return false;
}

TEST(GibiNodeNames, CornersThenEdgesInTheScriptsOrder) {
  Mesh mesh = tools::make_ssnp121_2d({});  // 12 QUAD4 on AB, 11 on EF: code_aster's SSNP121 A
  const Mesh before = mesh;
  tools::name_nodes_as_gibi_script(mesh);
  // Only the names change, each used once.
  EXPECT_EQ(mesh.coords, before.coords);
  EXPECT_EQ(mesh.cell_nodes, before.cell_nodes);
  EXPECT_EQ(std::set<std::string>(mesh.node_names.begin(), mesh.node_names.end()).size(), mesh.node_names.size());
  // a, b, c, d of PLAQUE1 then e, f, g, h of PLAQUE2 (a and e, b and f coincide: one per block).
  const double corners[8][2] = {{-1, 0}, {1, 0}, {1, 1}, {-1, 1}, {-1, 0}, {1, 0}, {1, -1}, {-1, -1}};
  for (int k = 0; k < 8; ++k) {
    const int n = node_named(mesh, "N" + std::to_string(k + 1));
    ASSERT_GE(n, 0);
    EXPECT_DOUBLE_EQ(mesh.coords[3 * n], corners[k][0]) << k;
    EXPECT_DOUBLE_EQ(mesh.coords[3 * n + 1], corners[k][1]) << k;
    EXPECT_TRUE(in_group(mesh, k < 4 ? "PLAQUE1" : "PLAQUE2", n)) << k;
  }
  // Then AB's 11 inner nodes from A to B: N9 at x = -5/6, N14 in the middle, N19 at x = 5/6; then
  // BC's from B up (N20).
  for (int k = 1; k <= 11; ++k) {
    const int n = node_named(mesh, "N" + std::to_string(8 + k));
    ASSERT_GE(n, 0);
    EXPECT_NEAR(mesh.coords[3 * n], -1.0 + k / 6.0, 1e-12) << k;
    EXPECT_EQ(mesh.coords[3 * n + 1], 0.0) << k;
    EXPECT_TRUE(in_group(mesh, "AB", n)) << k;
  }
  const int n20 = node_named(mesh, "N20");
  EXPECT_DOUBLE_EQ(mesh.coords[3 * n20], 1.0);
  EXPECT_NEAR(mesh.coords[3 * n20 + 1], 1.0 / 12.0, 1e-12);
  EXPECT_EQ(mesh.node_groups.at("O"), std::vector<int>{node_named(mesh, "N14")});
}

TEST(GibiNodeNames, GluedBlocksHaveNoScriptNames) {
  tools::Ssnp121Options2d o;
  o.lower = o.upper;
  o.glued = true;
  Mesh mesh = tools::make_ssnp121_2d(o);
  EXPECT_THROW(tools::name_nodes_as_gibi_script(mesh), DeckError);
}

}  // namespace
}  // namespace lunaster
