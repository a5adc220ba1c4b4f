// Normals at the nodes of a skin whose cells are oriented either way (LIAISON_MAIL's DDL = 'DNOR').
#include <gtest/gtest.h>

#include <cmath>

#include "engine/contact/surface_element.hpp"

namespace lunaster::engine::contact {
namespace {

TEST(SurfaceElement, NodeNormalsAgreeAcrossFacesOrientedEitherWay) {
  Mesh mesh;  // two unit squares in the plane z = 1 sharing the edge x = 1, the second one reversed
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 1; ++j) mesh.add_node(i, j, 1.0);
  auto id = [](int i, int j) { return 2 * i + j; };
  const int up = mesh.add_cell(CellType::Quad4, {id(0, 0), id(1, 0), id(1, 1), id(0, 1)});
  const int down = mesh.add_cell(CellType::Quad4, {id(1, 0), id(1, 1), id(2, 1), id(2, 0)});
  const auto normals = node_normals(mesh, {up, down});
  ASSERT_EQ(normals.size(), 6u);
  for (const auto& [node, n] : normals) {
    EXPECT_NEAR(n[0], 0.0, 1e-15) << "node " << node;
    EXPECT_NEAR(n[1], 0.0, 1e-15) << "node " << node;
    EXPECT_NEAR(std::abs(n[2]), 1.0, 1e-15) << "node " << node;  // the shared edge's too: no cancelling
  }
  Mesh line;  // a SEG2 along x: normal along y
  line.add_node(0.0, 0.0, 0.0);
  line.add_node(2.0, 0.0, 0.0);
  const int seg = line.add_cell(CellType::Seg2, {0, 1});
  const auto n2 = node_normals(line, {seg});
  EXPECT_NEAR(std::abs(n2.at(0)[1]), 1.0, 1e-15);
  EXPECT_NEAR(n2.at(1)[0], 0.0, 1e-15);
}

}  // namespace
}  // namespace lunaster::engine::contact
