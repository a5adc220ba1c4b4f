// Contact weights of an AXIS model: the discrete formulation's tributary measures are the
// integrals of the slave nodes' linear shape functions times r (per radian), like the
// AXIS elements' consistent nodal forces of a uniform pressure.
#include <gtest/gtest.h>

#include <vector>

#include "engine/contact/discretisation.hpp"

namespace lunaster::engine::contact {
namespace {

TEST(AxisContactWeights, NodeToSegmentTributaryMeasureIsWeightedByRadius) {
  // Slave line along r from the axis: SEG2 (0,0)-(1,0) and (1,0)-(2,0).
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  mesh.node_names = {"N1", "N2", "N3"};
  mesh.cell_types = {CellType::Seg2, CellType::Seg2};
  mesh.cell_nodes = {0, 1, 1, 2};
  mesh.cell_offsets = {0, 2, 4};
  mesh.cell_names = {"M1", "M2"};
  ContactZone zone;
  zone.slave_cells = {0, 1};
  for (bool axis : {false, true}) {
    std::vector<ContactPoint> points;
    make_node_to_segment(axis)->build_points(mesh, 2, 0, zone, points);
    ASSERT_EQ(points.size(), 3u);
    // int N_a r dr: 1/6 (on the axis), 1/3 + 2/3, 5/6; plane: 1/2, 1, 1/2.
    const double expected[2][3] = {{0.5, 1.0, 0.5}, {1.0 / 6.0, 1.0, 5.0 / 6.0}};
    for (const auto& p : points) EXPECT_NEAR(p.weight, expected[axis][p.slave_nodes[0]], 1e-14) << axis;
  }
}

}  // namespace
}  // namespace lunaster::engine::contact
