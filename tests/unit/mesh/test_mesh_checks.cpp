// VERI_MAIL's checks: cells listing a node twice, cells of one type on the same nodes, flat cells.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/mesh/mesh_checks.hpp"

namespace lunaster::engine {
namespace {

TEST(MeshChecks, RepeatedNodesDuplicateCellsAndFlatCells) {
  Mesh mesh;
  mesh.add_node(0, 0, 0);
  mesh.add_node(1, 0, 0);
  mesh.add_node(1, 1, 0);
  mesh.add_node(2, 0, 0);
  mesh.add_node(2, 1e-5, 0);
  mesh.add_cell(CellType::Tria3, {0, 1, 2});  // M1
  mesh.add_cell(CellType::Seg2, {2, 0});      // M2
  mesh.add_cell(CellType::Seg2, {0, 2});      // M3: M2's nodes in the other order
  mesh.add_cell(CellType::Tria3, {0, 2, 1});  // M4: M1's nodes
  mesh.add_cell(CellType::Seg2, {1, 1});      // M5
  mesh.add_cell(CellType::Tria3, {1, 3, 4});  // M6: flat, shortest 1e-5, longest sqrt(1 + 1e-10)
  mesh.add_cell(CellType::Point1, {3});       // M7
  EXPECT_EQ(cells_repeating_a_node(mesh), std::vector<int>{4});
  EXPECT_EQ(duplicate_cells(mesh), (std::vector<std::pair<int, int>>{{0, 3}, {1, 2}}));
  const auto flat = flat_cells(mesh, 1e-3);
  ASSERT_EQ(flat.size(), 1u);  // M5's nodes coincide: no longest distance, left to the check above
  EXPECT_EQ(flat[0].first, 5);
  EXPECT_NEAR(flat[0].second, 1e-5 / std::sqrt(1 + 1e-10), 1e-15);
  EXPECT_TRUE(flat_cells(mesh, 1e-6).empty());
}

}  // namespace
}  // namespace lunaster::engine
