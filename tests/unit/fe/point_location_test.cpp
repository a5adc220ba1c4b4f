// Locating points in cells (LIAISON_MAIL's ties): reference coordinates by Newton on distorted
// and curved cells of every face and volume type, the cell found among several, and the
// nearest cell for a point outside them all.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/fe/point_location.hpp"
#include "engine/fe/shape.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::type_name;

/// Node coordinates of a distorted cell: x = A xi + b, plus a bulge on quadratic mid-side nodes.
std::vector<double> distorted_cell(CellType type) {
  const CellInfo& info = cell_info(type);
  std::vector<double> xyz(3 * info.n_nodes, 0.0);
  for (int a = 0; a < info.n_nodes; ++a) {
    double r[3] = {0, 0, 0};
    reference_node(type, a, r);
    double* x = &xyz[3 * a];
    x[0] = 1.3 * r[0] + 0.2 * r[1] + 0.1 * r[2] + 4.0;
    x[1] = -0.1 * r[0] + 0.9 * r[1] + 0.15 * r[2] - 2.0;
    x[2] = info.dim == 3 ? 0.05 * r[0] - 0.1 * r[1] + 1.1 * r[2] + 0.5 : 0.0;
    if (a >= info.n_vertices) x[0] += 0.04, x[1] -= 0.03;  // curved edges
  }
  return xyz;
}

TEST(PointLocation, NewtonFindsTheReferenceCoordinatesOfEveryFaceAndVolumeType) {
  for (CellType type : {CellType::Tria3, CellType::Tria6, CellType::Quad4, CellType::Quad8, CellType::Tetra4,
                        CellType::Tetra10, CellType::Penta6, CellType::Penta15, CellType::Hexa8, CellType::Hexa20}) {
    SCOPED_TRACE(type_name(type));
    const std::vector<double> xyz = distorted_cell(type);
    const bool simplex = type == CellType::Tria3 || type == CellType::Tria6 || type == CellType::Tetra4 ||
                         type == CellType::Tetra10;
    const bool prism = type == CellType::Penta6 || type == CellType::Penta15;
    const double xi0[3] = {simplex || prism ? 0.2 : -0.37, simplex || prism ? 0.3 : 0.61,
                           simplex ? 0.15 : -0.44};
    double n[kMaxCellNodes];
    shape_functions(type, xi0, n, nullptr);
    double point[3] = {0, 0, 0};
    for (int a = 0; a < cell_info(type).n_nodes; ++a)
      for (int i = 0; i < 3; ++i) point[i] += n[a] * xyz[3 * a + i];
    double xi[3];
    ASSERT_TRUE(reference_coordinates(type, xyz.data(), point, xi));
    for (int i = 0; i < cell_info(type).dim; ++i) EXPECT_NEAR(xi[i], xi0[i], 1e-13) << "coordinate " << i;
    EXPECT_TRUE(inside_reference(type, xi, 1e-12));
    // Out of the cell: found, then clamped onto it.
    double far_xi[3] = {xi0[0], xi0[1], xi0[2]};
    far_xi[0] += simplex || prism ? 1.2 : 1.6;
    shape_functions(type, far_xi, n, nullptr);
    double outside[3] = {0, 0, 0};
    for (int a = 0; a < cell_info(type).n_nodes; ++a)
      for (int i = 0; i < 3; ++i) outside[i] += n[a] * xyz[3 * a + i];
    ASSERT_TRUE(reference_coordinates(type, xyz.data(), outside, xi));
    EXPECT_FALSE(inside_reference(type, xi, 1e-12));
    clamp_to_reference(type, xi);
    EXPECT_TRUE(inside_reference(type, xi, 1e-14));
  }
}

/// Two HEXA8 cells [0,1]x[0,1]x[0,1] and [1,2]x[0,1]x[0,1] sharing the face x = 1.
Mesh two_hexa() {
  Mesh mesh;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 1; ++j)
      for (int k = 0; k <= 1; ++k) mesh.add_node(i, j, k);
  auto id = [](int i, int j, int k) { return 4 * i + 2 * j + k; };
  for (int i = 0; i < 2; ++i)  // MED HEXA8 order: bottom face, then top, each turning one way
    mesh.add_cell(CellType::Hexa8, {id(i, 0, 0), id(i, 1, 0), id(i + 1, 1, 0), id(i + 1, 0, 0), id(i, 0, 1),
                                    id(i, 1, 1), id(i + 1, 1, 1), id(i + 1, 0, 1)});
  return mesh;
}

TEST(PointLocation, LocatorPicksTheCellThatHoldsThePointOrTheNearest) {
  const Mesh mesh = two_hexa();
  const CellLocator locator(mesh, {0, 1});
  const double in_second[3] = {1.75, 0.25, 0.5};
  PointLocation loc = locator.locate(in_second);
  EXPECT_EQ(loc.cell, 1);
  EXPECT_TRUE(loc.inside);
  EXPECT_EQ(loc.distance, 0.0);
  double n[kMaxCellNodes];
  shape_functions(CellType::Hexa8, loc.xi, n, nullptr);
  double x[3] = {0, 0, 0};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) x[i] += n[a] * mesh.node(mesh.cell(1)[a])[i];
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], in_second[i], 1e-14);

  const double on_shared_face[3] = {1.0, 0.5, 0.5};  // in both cells: the lower index
  loc = locator.locate(on_shared_face);
  EXPECT_EQ(loc.cell, 0);
  EXPECT_TRUE(loc.inside);

  const double beyond[3] = {2.3, 0.5, 0.25};  // 0.3 past the face x = 2 of the second cell
  loc = locator.locate(beyond);
  EXPECT_EQ(loc.cell, 1);
  EXPECT_FALSE(loc.inside);
  EXPECT_NEAR(loc.distance, 0.3, 1e-14);

  const double far_below[3] = {0.4, 0.5, -5.0};  // far from both: still the nearest, by distance
  loc = locator.locate(far_below);
  EXPECT_EQ(loc.cell, 0);
  EXPECT_NEAR(loc.distance, 5.0, 1e-13);

  // Thousands of cell sizes away, where Newton gives up: the nearest cell by its nearest node.
  const double very_far[3] = {3000.0, 0.0, 0.0};
  loc = locator.locate(very_far);
  EXPECT_EQ(loc.cell, 1);
  EXPECT_FALSE(loc.inside);
  EXPECT_NEAR(loc.distance, 2998.0, 1e-9);
  EXPECT_EQ(loc.xi[0], 1.0);  // the node (2, 0, 0): reference (1, -1, -1) in the second cell
  EXPECT_EQ(loc.xi[1], -1.0);
}

TEST(PointLocation, LocatorOnAGridOfQuadrangles) {
  Mesh mesh;  // 4 x 3 QUAD4 on [0, 2] x [0, 1.5], interior vertices moved
  const int nx = 4, ny = 3;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool interior = i > 0 && i < nx && j > 0 && j < ny;
      mesh.add_node(0.5 * i + (interior ? 0.07 * ((i + j) % 3 - 1) : 0.0),
                    0.5 * j + (interior ? 0.05 * ((i * j) % 3 - 1) : 0.0), 0.0);
    }
  std::vector<int> cells;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      cells.push_back(mesh.add_cell(CellType::Quad4, {a, a + 1, a + nx + 2, a + nx + 1}));
    }
  const CellLocator locator(mesh, cells);
  for (int k = 0; k < 200; ++k) {
    const double p[3] = {0.01 + 1.98 * std::fmod(0.6180339887 * k, 1.0), 0.01 + 1.48 * std::fmod(0.7548776662 * k, 1.0),
                         0.0};
    const PointLocation loc = locator.locate(p);
    ASSERT_GE(loc.cell, 0);
    EXPECT_TRUE(loc.inside) << "point " << p[0] << ", " << p[1];
    double n[kMaxCellNodes];
    shape_functions(CellType::Quad4, loc.xi, n, nullptr);
    double x[2] = {0, 0};
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 2; ++i) x[i] += n[a] * mesh.node(mesh.cell(loc.cell)[a])[i];
    EXPECT_NEAR(x[0], p[0], 1e-14);
    EXPECT_NEAR(x[1], p[1], 1e-14);
  }
}

}  // namespace
}  // namespace lunaster::engine
