// A mesh as the byte block rank 0 sends the other ranks after reading a mesh file once.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.hpp"
#include "engine/mesh/mesh_bytes.hpp"
#include "tools/ssnp121_mesh.hpp"

namespace lunaster::engine {
namespace {

using tools::make_ssnp121_2d;
using tools::make_ssnp121_3d;
using tools::Ssnp121Options2d;
using tools::Ssnp121Options3d;

void expect_identical(const Mesh& a, const Mesh& b) {
  EXPECT_EQ(a.dim, b.dim);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.coords, b.coords);  // bit for bit
  EXPECT_EQ(a.node_names, b.node_names);
  EXPECT_EQ(a.cell_types, b.cell_types);
  EXPECT_EQ(a.cell_offsets, b.cell_offsets);
  EXPECT_EQ(a.cell_nodes, b.cell_nodes);
  EXPECT_EQ(a.cell_names, b.cell_names);
  EXPECT_EQ(a.node_groups, b.node_groups);
  EXPECT_EQ(a.cell_groups, b.cell_groups);
}

TEST(MeshBytes, EveryMemberComesBackIdentical) {
  // The 3D SSNP121 mesh (HEXA8 and HEXA20 volumes, QUAD4 and QUAD8 faces, node and cell
  // groups), renamed and given a node with a long name and one with an empty group.
  Ssnp121Options3d options;
  Mesh mesh = make_ssnp121_3d(options);
  mesh.name = "bloc et patin";
  mesh.node_names[0] = std::string(300, 'x');
  mesh.coords[1] = -1.0 / 3.0;
  mesh.add_to_node_group("EMPTY", {});
  ASSERT_GT(mesh.cell_groups.size(), 2u);
  ASSERT_GT(mesh.node_groups.size(), 2u);
  const Mesh back = mesh_from_bytes(mesh_to_bytes(mesh));
  expect_identical(mesh, back);
  EXPECT_EQ(back.find_node(std::string(300, 'x')), 0);
  EXPECT_EQ(back.find_cell(mesh.cell_names.back()), mesh.n_cells() - 1);
}

TEST(MeshBytes, TwoDimensionalAndEmptyMeshes) {
  const Mesh mesh2d = make_ssnp121_2d(Ssnp121Options2d{});
  expect_identical(mesh2d, mesh_from_bytes(mesh_to_bytes(mesh2d)));
  const Mesh empty;
  expect_identical(empty, mesh_from_bytes(mesh_to_bytes(empty)));
}

TEST(MeshBytes, ArraysAfterTheMeshComeBackInOrder) {
  const Mesh mesh = make_ssnp121_2d(Ssnp121Options2d{});
  const std::vector<int> first{3, -1, 7}, empty, second{42};
  const std::string bytes = mesh_to_bytes(mesh, {&first, &empty, &second});
  std::vector<int> a{9}, b{9}, c;
  expect_identical(mesh, mesh_from_bytes(bytes, {&a, &b, &c}));
  EXPECT_EQ(a, first);
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(c, second);
  // Another count of arrays than written is refused, and so is a mesh read without them.
  EXPECT_THROW(mesh_from_bytes(bytes, {&a, &b}), InternalError);
  EXPECT_THROW(mesh_from_bytes(bytes), InternalError);
}

TEST(MeshBytes, TruncatedOrAlteredBlocksAreRefused) {
  const Mesh mesh = make_ssnp121_2d(Ssnp121Options2d{});
  const std::string bytes = mesh_to_bytes(mesh);
  EXPECT_THROW(mesh_from_bytes(bytes.substr(0, bytes.size() - 1)), InternalError);
  EXPECT_THROW(mesh_from_bytes(bytes.substr(0, bytes.size() / 2)), InternalError);
  EXPECT_THROW(mesh_from_bytes(bytes + "x"), InternalError);
  std::string other = bytes;
  other[0] ^= 1;  // not a mesh block
  EXPECT_THROW(mesh_from_bytes(other), InternalError);
}

}  // namespace
}  // namespace lunaster::engine
