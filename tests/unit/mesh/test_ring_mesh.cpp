// The ring/sleeve generator (lunaster-meshgen --ring/--sleeve) of the curved mortar
// verification case: counts, nodes exactly on their circles and symmetry lines, groups,
// outward boundary cells, non-matching interface, MED round trip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "engine/core/error.hpp"
#include "engine/mesh/orientation.hpp"
#include "test_helpers.hpp"
#include "tools/ssnp121_mesh.hpp"

namespace lunaster::engine {
namespace {

tools::RingOptions options(const char* ring, const char* sleeve) {
  tools::RingOptions o;
  o.ring = tools::parse_block_cells(ring, 2);
  o.sleeve = tools::parse_block_cells(sleeve, 2);
  return o;
}

double radius(const Mesh& m, int n) { return std::hypot(m.node(n)[0], m.node(n)[1]); }

std::vector<int> group_nodes(const Mesh& m, const std::string& g) { return m.nodes_of_cells(m.cell_groups.at(g)); }

int count_type(const Mesh& m, CellType t) {
  return static_cast<int>(std::count(m.cell_types.begin(), m.cell_types.end(), t));
}

/// Nodes of an NT x NR structured annulus: (NT+1)(NR+1) vertices, plus one per edge for QUAD8.
int annulus_nodes(CellType t, int nt, int nr) {
  const int vertices = (nt + 1) * (nr + 1);
  return t == CellType::Quad8 ? vertices + nt * (nr + 1) + (nt + 1) * nr : vertices;
}

TEST(RingMesh, CountsAndGroupSizes) {
  for (const auto& [ring, sleeve] : std::vector<std::pair<const char*, const char*>>{
           {"quad4:12x4", "quad4:9x3"}, {"quad8:6x2", "quad8:5x2"}, {"quad4:7x2", "quad8:4x3"}}) {
    const tools::RingOptions o = options(ring, sleeve);
    const Mesh m = tools::make_ring_sleeve(o);
    const int nt1 = o.ring.n[0], nr1 = o.ring.n[1], nt2 = o.sleeve.n[0], nr2 = o.sleeve.n[1];
    const int per_edge1 = o.ring.type == CellType::Quad8 ? 2 : 1, per_edge2 = o.sleeve.type == CellType::Quad8 ? 2 : 1;
    EXPECT_EQ(m.dim, 2) << ring;
    EXPECT_EQ(m.n_nodes(), annulus_nodes(o.ring.type, nt1, nr1) + annulus_nodes(o.sleeve.type, nt2, nr2)) << ring;
    EXPECT_EQ(m.cell_groups.at("RING").size(), static_cast<size_t>(nt1 * nr1)) << ring;
    EXPECT_EQ(m.cell_groups.at("SLEEVE").size(), static_cast<size_t>(nt2 * nr2)) << ring;
    for (const char* g : {"INNER", "RING_OUT"}) EXPECT_EQ(m.cell_groups.at(g).size(), static_cast<size_t>(nt1)) << g;
    for (const char* g : {"SLEEVE_IN", "OUTER"}) EXPECT_EQ(m.cell_groups.at(g).size(), static_cast<size_t>(nt2)) << g;
    for (const char* g : {"X0_RING", "Y0_RING"}) EXPECT_EQ(m.cell_groups.at(g).size(), static_cast<size_t>(nr1)) << g;
    for (const char* g : {"X0_SLEEVE", "Y0_SLEEVE"}) EXPECT_EQ(m.cell_groups.at(g).size(), static_cast<size_t>(nr2)) << g;
    EXPECT_EQ(group_nodes(m, "RING_OUT").size(), static_cast<size_t>(per_edge1 * nt1 + 1)) << ring;
    EXPECT_EQ(group_nodes(m, "SLEEVE_IN").size(), static_cast<size_t>(per_edge2 * nt2 + 1)) << ring;
    // every cell is a volume cell of one body or a boundary cell of exactly one group
    const int n_boundary = 2 * nt1 + 2 * nr1 + 2 * nt2 + 2 * nr2;
    EXPECT_EQ(m.n_cells(), nt1 * nr1 + nt2 * nr2 + n_boundary) << ring;
    EXPECT_EQ(count_type(m, CellType::Seg2) + count_type(m, CellType::Seg3), n_boundary) << ring;
    EXPECT_EQ(m.node_groups.size(), 8u);
    for (const auto& [name, nodes] : m.node_groups) EXPECT_EQ(nodes.size(), 1u) << name;
  }
}

TEST(RingMesh, ArcNodesOnTheirCirclesAndSymmetryNodesOnTheAxes) {
  for (const char* type : {"quad4:13x3", "quad8:11x3"}) {
    tools::RingOptions o = options(type, type);
    o.sleeve.n[0] = o.ring.n[0] - 2;  // non-matching
    const Mesh m = tools::make_ring_sleeve(o);
    for (const auto& [g, r] : std::vector<std::pair<std::string, double>>{
             {"INNER", o.a}, {"RING_OUT", o.b}, {"SLEEVE_IN", o.b}, {"OUTER", o.c}})
      for (int n : group_nodes(m, g)) EXPECT_NEAR(radius(m, n), r, 1e-14) << type << " " << g << " node " << n;
    // every node of the mesh lies on a circle of the radial lattice, inside the quarter plane
    for (int n = 0; n < m.n_nodes(); ++n) {
      EXPECT_GE(m.node(n)[0], 0.0);
      EXPECT_GE(m.node(n)[1], 0.0);
      EXPECT_EQ(m.node(n)[2], 0.0);
      EXPECT_GE(radius(m, n), o.a - 1e-14);
      EXPECT_LE(radius(m, n), o.c + 1e-14);
    }
    for (const char* g : {"X0_RING", "X0_SLEEVE"})
      for (int n : group_nodes(m, g)) EXPECT_EQ(m.node(n)[0], 0.0) << g;
    for (const char* g : {"Y0_RING", "Y0_SLEEVE"})
      for (int n : group_nodes(m, g)) EXPECT_EQ(m.node(n)[1], 0.0) << g;
    const auto at = [&](const char* g) { return m.node(m.node_groups.at(g)[0]); };
    for (const auto& [g, x, y] : std::vector<std::tuple<const char*, double, double>>{
             {"A_X", o.a, 0}, {"A_Y", 0, o.a}, {"P_X", o.b, 0}, {"P_Y", 0, o.b},
             {"Q_X", o.b, 0}, {"Q_Y", 0, o.b}, {"C_X", o.c, 0}, {"C_Y", 0, o.c}}) {
      EXPECT_EQ(at(g)[0], x) << g;
      EXPECT_EQ(at(g)[1], y) << g;
    }
    // the interface end points are duplicated: P_X in the ring, Q_X in the sleeve
    const auto ring_nodes = m.nodes_of_cells(m.cell_groups.at("RING"));
    const auto sleeve_nodes = m.nodes_of_cells(m.cell_groups.at("SLEEVE"));
    std::vector<int> shared;
    std::set_intersection(ring_nodes.begin(), ring_nodes.end(), sleeve_nodes.begin(), sleeve_nodes.end(),
                          std::back_inserter(shared));
    EXPECT_TRUE(shared.empty()) << type;
    EXPECT_TRUE(std::binary_search(ring_nodes.begin(), ring_nodes.end(), m.node_groups.at("P_X")[0]));
    EXPECT_TRUE(std::binary_search(sleeve_nodes.begin(), sleeve_nodes.end(), m.node_groups.at("Q_Y")[0]));
  }
}

TEST(RingMesh, Quad8ArcEdgesAreCurvedAndRadialEdgesStraight) {
  const tools::RingOptions o = options("quad8:5x2", "quad8:4x2");
  const Mesh m = tools::make_ring_sleeve(o);
  for (const char* g : {"INNER", "RING_OUT", "SLEEVE_IN", "OUTER"})
    for (int c : m.cell_groups.at(g)) {
      ASSERT_EQ(m.cell_types[c], CellType::Seg3);
      const double* p = m.node(m.cell(c)[0]);
      const double* q = m.node(m.cell(c)[1]);
      const double* mid = m.node(m.cell(c)[2]);
      // the mid node halves the angle and is off the chord (the edge is curved)
      const double t0 = std::atan2(p[1], p[0]), t1 = std::atan2(q[1], q[0]), tm = std::atan2(mid[1], mid[0]);
      EXPECT_NEAR(tm, 0.5 * (t0 + t1), 1e-14) << g;
      EXPECT_GT(std::hypot(mid[0] - 0.5 * (p[0] + q[0]), mid[1] - 0.5 * (p[1] + q[1])), 1e-3) << g;
    }
  for (const char* g : {"X0_RING", "Y0_RING", "X0_SLEEVE", "Y0_SLEEVE"})
    for (int c : m.cell_groups.at(g))
      for (int d = 0; d < 2; ++d)
        EXPECT_NEAR(m.node(m.cell(c)[2])[d], 0.5 * (m.node(m.cell(c)[0])[d] + m.node(m.cell(c)[1])[d]), 1e-15) << g;
}

TEST(RingMesh, CellsCounterClockwiseAndBoundaryOutward) {
  for (const char* type : {"quad4:6x2", "quad8:6x2"}) {
    tools::RingOptions o = options(type, type);
    o.sleeve.n[0] = 5;
    Mesh m = tools::make_ring_sleeve(o);
    EXPECT_TRUE(find_inverted_cells(m).empty()) << type;
    // outward normals: INNER faces the centre, RING_OUT away from it, the sleeve the other way
    const auto radial = [&](int c) {
      const auto nrm = boundary_normal(m, c);
      const double* p = m.node(m.cell(c)[0]);
      const double* q = m.node(m.cell(c)[1]);
      const double mx = 0.5 * (p[0] + q[0]), my = 0.5 * (p[1] + q[1]);
      return (nrm[0] * mx + nrm[1] * my) / (std::hypot(nrm[0], nrm[1]) * std::hypot(mx, my));
    };
    for (int c : m.cell_groups.at("INNER")) EXPECT_LT(radial(c), -0.99) << type;
    for (int c : m.cell_groups.at("RING_OUT")) EXPECT_GT(radial(c), 0.99) << type;
    for (int c : m.cell_groups.at("SLEEVE_IN")) EXPECT_LT(radial(c), -0.99) << type;
    for (int c : m.cell_groups.at("OUTER")) EXPECT_GT(radial(c), 0.99) << type;
    for (const char* g : {"X0_RING", "X0_SLEEVE"})
      for (int c : m.cell_groups.at(g)) EXPECT_LT(boundary_normal(m, c)[0], 0.0) << g;
    for (const char* g : {"Y0_RING", "Y0_SLEEVE"})
      for (int c : m.cell_groups.at(g)) EXPECT_LT(boundary_normal(m, c)[1], 0.0) << g;
    for (const char* g : {"INNER", "RING_OUT", "SLEEVE_IN", "OUTER", "X0_RING", "Y0_RING", "X0_SLEEVE", "Y0_SLEEVE"})
      EXPECT_EQ(orient_boundary_outward(m, m.cell_groups.at(g)), 0) << type << " " << g;
  }
}

TEST(RingMesh, Quad4AreaIsThePolygonalSector) {
  const tools::RingOptions o = options("quad4:10x3", "quad4:7x2");
  const Mesh m = tools::make_ring_sleeve(o);
  const auto area = [&](const char* g) {
    double s = 0.0;
    for (int c : m.cell_groups.at(g)) s += cell_measure(m, c);
    return s;
  };
  // NT trapezoids between chords: NT/2 (r1^2 - r0^2) sin(pi / (2 NT))
  EXPECT_NEAR(area("RING"), 10 * 0.5 * (o.b * o.b - o.a * o.a) * std::sin(M_PI / 20), 1e-14);
  EXPECT_NEAR(area("SLEEVE"), 7 * 0.5 * (o.c * o.c - o.b * o.b) * std::sin(M_PI / 14), 1e-14);
}

TEST(RingMesh, MedRoundTripKeepsCoordinatesAndGroups) {
  testing::expect_med_round_trip(tools::make_ring_sleeve(options("quad8:4x2", "quad4:3x2")), "ring");
}

TEST(RingMesh, RefusesOtherCellTypesAndBadRadii) {
  EXPECT_THROW(tools::make_ring_sleeve(options("tria3:4x2", "quad4:4x2")), DeckError);
  EXPECT_THROW(tools::make_ring_sleeve(options("quad4:4x2", "tria6:4x2")), DeckError);
  tools::RingOptions o = options("quad4:4x2", "quad4:3x2");
  o.b = 1.2;
  EXPECT_THROW(tools::make_ring_sleeve(o), DeckError);
  o.b = 0.75;
  o.a = 0.0;
  EXPECT_THROW(tools::make_ring_sleeve(o), DeckError);
}

}  // namespace
}  // namespace lunaster::engine
