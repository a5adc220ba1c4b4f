// Cell type tables: info, outward faces of the MED reference cells.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/mesh/cell_type.hpp"
#include "engine/mesh/orientation.hpp"
#include "test_helpers.hpp"

namespace lunaster::engine {
namespace {

using testing::all_cell_types;
using testing::reference_nodes;
using Vec3 = std::array<double, 3>;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

TEST(CellType, InfoIsConsistentAndNamesRoundTrip) {
  for (CellType t : all_cell_types()) {
    const CellInfo& info = cell_info(t);
    EXPECT_EQ(info.type, t);
    EXPECT_EQ(static_cast<int>(reference_nodes(t).size()), info.n_nodes) << info.name;
    EXPECT_EQ(info.n_nodes, info.n_vertices + static_cast<int>(cell_mid_edges(t).size())) << info.name;
    CellType back;
    ASSERT_TRUE(cell_type_from_name(info.name, back));
    EXPECT_EQ(back, t);
  }
  CellType t;
  EXPECT_FALSE(cell_type_from_name("QUAD9", t));
  EXPECT_TRUE(cell_type_from_name("PYRA5", t));
  EXPECT_EQ(t, CellType::Pyram5);
}

TEST(CellType, FacesOfReferenceCellsPointOutwardAndCloseTheSurface) {
  for (CellType t : all_cell_types()) {
    const CellInfo& info = cell_info(t);
    if (info.dim < 2) continue;
    const auto x = reference_nodes(t);
    Vec3 centre{0, 0, 0};
    for (int i = 0; i < info.n_vertices; ++i)
      for (int k = 0; k < 3; ++k) centre[k] += x[i][k] / info.n_vertices;
    const CellFaces& faces = cell_faces(t);
    Vec3 total{0, 0, 0};
    int node_use = 0;
    for (int f = 0; f < faces.n_faces; ++f) {
      const CellInfo& fi = cell_info(faces.face_type[f]);
      const auto& n = faces.nodes[f];
      Vec3 normal;
      if (info.dim == 2) {
        const Vec3 tangent = sub(x[n[1]], x[n[0]]);
        normal = {tangent[1], -tangent[0], 0.0};
      } else {
        normal = cross(sub(x[n[1]], x[n[0]]), sub(x[n[2]], x[n[0]]));
      }
      Vec3 face_centre{0, 0, 0};
      for (int k = 0; k < fi.n_vertices; ++k)
        for (int d = 0; d < 3; ++d) face_centre[d] += x[n[k]][d] / fi.n_vertices;
      EXPECT_GT(dot(normal, sub(face_centre, centre)), 1e-12) << info.name << " face " << f;
      // quadratic faces: vertices first, then the mid-side nodes of consecutive vertices
      for (int k = fi.n_vertices; k < fi.n_nodes; ++k) {
        const int a = n[k - fi.n_vertices], b = n[(k - fi.n_vertices + 1) % fi.n_vertices];
        for (int d = 0; d < 3; ++d) EXPECT_DOUBLE_EQ(x[n[k]][d], 0.5 * (x[a][d] + x[b][d])) << info.name;
      }
      if (fi.n_nodes < 8) {
        EXPECT_EQ(n[fi.n_nodes], -1) << info.name << ": face list must end with -1";
      }
      // area vector of the (planar) face, summed over all faces: zero for a closed surface
      if (info.dim == 3) {
        Vec3 area{0, 0, 0};
        for (int k = 1; k + 1 < fi.n_vertices; ++k) {
          const Vec3 c = cross(sub(x[n[k]], x[n[0]]), sub(x[n[k + 1]], x[n[0]]));
          for (int d = 0; d < 3; ++d) area[d] += 0.5 * c[d];
        }
        for (int d = 0; d < 3; ++d) total[d] += area[d];
      }
      node_use += fi.n_vertices;
    }
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(total[d], 0.0, 1e-12) << info.name;
    // each vertex of a 2D cell is on 2 edges; 3D: sum of vertex valences = 2 * n_edges
    const int expected_use = info.dim == 2 ? 2 * info.n_vertices
                             : t == CellType::Tetra4 || t == CellType::Tetra10 ? 12
                             : t == CellType::Pyram5                           ? 16
                             : t == CellType::Penta6 || t == CellType::Penta15 ? 18
                                                                               : 24;
    EXPECT_EQ(node_use, expected_use) << info.name;
  }
}

TEST(CellType, ReferenceCellsHavePositiveMeasureAndReversalFlipsNormals) {
  for (CellType t : all_cell_types()) {
    Mesh mesh;
    const int c = testing::add_reference_cell(mesh, t);
    mesh.detect_dimension();
    const CellInfo& info = cell_info(t);
    const double expected = t == CellType::Tetra4 || t == CellType::Tetra10 ? 1.0 / 6
                            : t == CellType::Pyram5                           ? 1.0 / 3
                            : t == CellType::Penta6 || t == CellType::Penta15 ? 0.5
                            : t == CellType::Tria3 || t == CellType::Tria6    ? 0.5
                                                                              : 1.0;
    if (info.dim >= 1) {
      EXPECT_NEAR(cell_measure(mesh, c), expected, 1e-14) << info.name;
    }
    if (info.dim == 1 || info.dim == 2) {
      const auto& perm = cell_reverse_permutation(t);
      ASSERT_EQ(static_cast<int>(perm.size()), info.n_nodes);
      Mesh reversed;
      const auto x = reference_nodes(t);
      std::vector<int> nodes;
      for (int k = 0; k < info.n_nodes; ++k) nodes.push_back(reversed.add_node(x[perm[k]][0], x[perm[k]][1], x[perm[k]][2]));
      reversed.add_cell(t, nodes);
      const auto n1 = boundary_normal(mesh, 0), n2 = boundary_normal(reversed, 0);
      EXPECT_LT(dot(n1, n2), 0.0) << info.name;
      // the reversed cell still has its mid-side nodes on the right edges
      for (size_t k = 0; k < cell_mid_edges(t).size(); ++k) {
        const auto [a, b] = cell_mid_edges(t)[k];
        const double* m = reversed.node(info.n_vertices + static_cast<int>(k));
        for (int d = 0; d < 3; ++d) EXPECT_DOUBLE_EQ(m[d], 0.5 * (reversed.node(a)[d] + reversed.node(b)[d]));
      }
    }
  }
}

}  // namespace
}  // namespace lunaster::engine
