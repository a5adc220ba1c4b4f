// Rigid rotation of a mesh (MODI_MAILLAGE ROTATION): exact images of known points, lengths and
// signed measures kept (so cells stay valid and boundary normals outward), 2D meshes kept at z = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/mesh/orientation.hpp"
#include "engine/mesh/transform.hpp"
#include "tools/ssnp121_mesh.hpp"

namespace lunaster::engine {
namespace {

constexpr double kPi = 3.14159265358979323846;

void expect_node(const Mesh& mesh, int n, double x, double y, double z) {
  EXPECT_NEAR(mesh.node(n)[0], x, 1e-14) << "node " << n;
  EXPECT_NEAR(mesh.node(n)[1], y, 1e-14) << "node " << n;
  EXPECT_NEAR(mesh.node(n)[2], z, 1e-14) << "node " << n;
}

TEST(RotateMesh, QuarterTurnAboutZThroughAPoint) {
  Mesh mesh;
  mesh.add_node(2, 1, 0);
  mesh.add_node(1, 1, 5);  // on the axis
  mesh.add_node(1, 2, -1);
  rotate_mesh(mesh, {1, 1, 0}, {0, 0, 2}, kPi / 2);  // the axis length does not matter
  expect_node(mesh, 0, 1, 2, 0);
  expect_node(mesh, 1, 1, 1, 5);
  expect_node(mesh, 2, 0, 1, -1);
  // the reversed axis turns the other way
  rotate_mesh(mesh, {1, 1, 0}, {0, 0, -1}, kPi / 2);
  expect_node(mesh, 0, 2, 1, 0);
}

TEST(RotateMesh, ThirdOfATurnAboutTheDiagonalPermutesTheAxes) {
  Mesh mesh;
  mesh.add_node(1, 0, 0);
  mesh.add_node(0, 1, 0);
  mesh.add_node(0, 0, 1);
  mesh.add_node(3, 3, 3);
  rotate_mesh(mesh, {0, 0, 0}, {1, 1, 1}, 2 * kPi / 3);
  expect_node(mesh, 0, 0, 1, 0);
  expect_node(mesh, 1, 0, 0, 1);
  expect_node(mesh, 2, 1, 0, 0);
  expect_node(mesh, 3, 3, 3, 3);
}

TEST(RotateMesh, TwoDimensionalMeshStaysInItsPlaneAndKeepsItsCells) {
  tools::Ssnp121Options2d options;
  options.upper = {CellType::Quad4, {3, 3, 1}};
  options.lower = {CellType::Quad8, {2, 2, 1}};
  Mesh mesh = tools::make_ssnp121_2d(options);
  std::vector<double> before;
  for (int c = 0; c < mesh.n_cells(); ++c) before.push_back(cell_measure(mesh, c));
  rotate_mesh(mesh, {0.3, -0.2, 0}, {0, 0, 1}, 30.0 * kPi / 180.0);
  for (int n = 0; n < mesh.n_nodes(); ++n) EXPECT_EQ(mesh.node(n)[2], 0.0);
  for (int c = 0; c < mesh.n_cells(); ++c) EXPECT_NEAR(cell_measure(mesh, c), before[c], 1e-14) << "cell " << c;
  EXPECT_TRUE(find_inverted_cells(mesh).empty());
  // A = (-1, 0) turned by 30 degrees about (0.3, -0.2)
  const int a = mesh.node_groups.at("A").front();
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  expect_node(mesh, a, 0.3 + c * (-1.3) - s * 0.2, -0.2 + s * (-1.3) + c * 0.2, 0);
}

TEST(RotateMesh, ThreeDimensionalMeshKeepsDistancesAndVolumes) {
  tools::Ssnp121Options3d options;
  options.v1 = {CellType::Hexa20, {2, 2, 2}};
  options.v2 = {CellType::Penta15, {2, 2, 2}};
  Mesh mesh = tools::make_ssnp121_3d(options);
  const Mesh original = mesh;
  rotate_mesh(mesh, {0.5, 0.5, 1}, {1, 2, 3}, 0.7);
  EXPECT_TRUE(find_inverted_cells(mesh).empty());
  for (int c = 0; c < mesh.n_cells(); ++c)
    EXPECT_NEAR(cell_measure(mesh, c), cell_measure(original, c), 1e-14) << "cell " << c;
  for (int n = 1; n < mesh.n_nodes(); ++n) {
    auto dist = [&](const Mesh& m) {
      return std::hypot(m.node(n)[0] - m.node(0)[0], m.node(n)[1] - m.node(0)[1], m.node(n)[2] - m.node(0)[2]);
    };
    EXPECT_NEAR(dist(mesh), dist(original), 1e-14) << "node " << n;
  }
  // boundary normals turn with the mesh: SURESC's stays the rotated +z (outward from V1)
  const int face = mesh.cell_groups.at("SURESC").front();
  const auto n0 = boundary_normal(original, face);
  const auto n1 = boundary_normal(mesh, face);
  Mesh probe;
  probe.add_node(n0[0], n0[1], n0[2]);
  rotate_mesh(probe, {0, 0, 0}, {1, 2, 3}, 0.7);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(n1[i], probe.node(0)[i], 1e-14);
}

TEST(RotateMesh, ZeroAxisIsAnInternalError) {
  Mesh mesh;
  mesh.add_node(1, 0, 0);
  EXPECT_THROW(rotate_mesh(mesh, {0, 0, 0}, {0, 0, 0}, 1.0), InternalError);
}

}  // namespace
}  // namespace lunaster::engine
