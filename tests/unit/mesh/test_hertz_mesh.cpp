// The Hertz contact meshes (lunaster-meshgen --hertz): ball on a block, 2D and 3D, linear
// and quadratic, graded or uniform. Counts against the lattice layout, cell quality
// (positive scaled Jacobians at every node), nodes of the curved side on the sphere,
// the grading (h0 at the contact, growth by G), groups on the right curves, total area and
// volume against the exact geometry, MED round trip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/fe/quadrature.hpp"
#include "engine/fe/shape.hpp"
#include "engine/mesh/orientation.hpp"
#include "test_helpers.hpp"
#include "tools/hertz_mesh.hpp"

namespace lunaster::engine {
namespace {

tools::HertzOptions opts(CellType type, int n, double grading, double r = 1.0, double w = 1.0, double h = 1.0) {
  tools::HertzOptions o;
  o.type = type;
  o.n = n;
  o.grading = grading;
  o.radius = r;
  o.width = w;
  o.height = h;
  return o;
}

/// Jacobian matrix of a cell's isoparametric map at the reference point xi (columns dX/dxi_k).
void jacobian(const Mesh& m, int c, const double* xi, double jac[3][3]) {
  const CellType t = m.cell_types[c];
  const int d = cell_info(t).dim, nn = m.cell_n_nodes(c);
  double dn[kMaxCellNodes * 3];
  shape_functions(t, xi, nullptr, dn);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) jac[i][k] = 0.0;
  for (int a = 0; a < nn; ++a)
    for (int k = 0; k < d; ++k)
      for (int i = 0; i < 3; ++i) jac[i][k] += m.node(m.cell(c)[a])[i] * dn[a * d + k];
}

double det(const double j[3][3], int d) {
  if (d == 2) return j[0][0] * j[1][1] - j[0][1] * j[1][0];
  return j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
         j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
}

/// Smallest scaled Jacobian det J / prod |dX/dxi_k| over the nodes of a volume cell
/// (1 for a square or cube, sin of the smallest corner angle for a parallelogram).
double scaled_jacobian(const Mesh& m, int c) {
  const CellType t = m.cell_types[c];
  const int d = cell_info(t).dim;
  double worst = 1e300;
  for (int k = 0; k < m.cell_n_nodes(c); ++k) {
    double xi[3] = {0, 0, 0}, j[3][3];
    reference_node(t, k, xi);
    jacobian(m, c, xi, j);
    double norms = 1.0;
    for (int col = 0; col < d; ++col) norms *= std::sqrt(j[0][col] * j[0][col] + j[1][col] * j[1][col] + j[2][col] * j[2][col]);
    worst = std::min(worst, det(j, d) / norms);
  }
  return worst;
}

/// Area (2D) or volume (3D) of a group's volume cells, integrated with the stiffness rule.
double measure(const Mesh& m, const std::string& group) {
  double sum = 0.0;
  for (int c : m.cell_groups.at(group)) {
    const int d = cell_info(m.cell_types[c]).dim;
    for (const auto& q : full_integration(m.cell_types[c])) {
      double j[3][3];
      jacobian(m, c, q.xi, j);
      sum += q.weight * det(j, d);
    }
  }
  return sum;
}

/// Distance of node n from the ball's centre (0, R) / (0, 0, R).
double from_centre(const Mesh& m, int n, double r) {
  const double* x = m.node(n);
  return m.dim == 2 ? std::hypot(x[0], x[1] - r) : std::sqrt(x[0] * x[0] + x[1] * x[1] + (x[2] - r) * (x[2] - r));
}

size_t group_size(const Mesh& m, const std::string& g) { return m.cell_groups.at(g).size(); }

TEST(HertzMesh, CellCountsFollowTheLayout2d) {
  for (const auto& o : {opts(CellType::Quad4, 40, 1.2), opts(CellType::Quad8, 12, 1.0), opts(CellType::Tria3, 60, 1.25, 1.0, 2.0, 1.5),
                        opts(CellType::Tria6, 10, 1.0, 1.0, 1.5, 1.0)}) {
    tools::HertzLayout lay;
    const Mesh m = tools::make_hertz(o, &lay);
    const std::string what = std::string(cell_info(o.type).name) + " G=" + std::to_string(o.grading);
    const int per_quad = linear_type(o.type) == CellType::Tria3 ? 2 : 1;
    const int mb = lay.m_ball, kb = lay.layers_ball;
    EXPECT_EQ(m.dim, 2) << what;
    EXPECT_EQ(group_size(m, "BALL"), static_cast<size_t>(per_quad * (mb * mb + 2 * mb * kb))) << what;
    EXPECT_EQ(group_size(m, "BALL_SURF"), static_cast<size_t>(mb + kb)) << what;
    EXPECT_EQ(group_size(m, "AXIS_BALL"), static_cast<size_t>(mb + kb)) << what;
    EXPECT_EQ(group_size(m, "BALL_TOP"), static_cast<size_t>(2 * mb)) << what;
    const int mx = lay.m_block[0], my = lay.m_block[1], kl = lay.layers_block;
    EXPECT_EQ(group_size(m, "BLOCK"), static_cast<size_t>(per_quad * (mx * my + kl * (mx + my)))) << what;
    EXPECT_EQ(group_size(m, "BLOCK_TOP"), static_cast<size_t>(mx + kl)) << what;
    EXPECT_EQ(group_size(m, "AXIS_BLOCK"), static_cast<size_t>(my + kl)) << what;
    EXPECT_EQ(group_size(m, "BLOCK_SIDE"), static_cast<size_t>(my)) << what;
    EXPECT_EQ(group_size(m, "BLOCK_BOTTOM"), static_cast<size_t>(mx)) << what;
    if (o.grading == 1.0) {  // uniform block: W/h0 x H/h0 cells
      EXPECT_EQ(mx, static_cast<int>(std::lround(o.width * o.n / o.radius))) << what;
      EXPECT_EQ(my, static_cast<int>(std::lround(o.height * o.n / o.radius))) << what;
      EXPECT_EQ(kl, 0) << what;
    } else {  // m = round(1/(G-1)) core cells, about log(size/(m h0))/log(G) layers
      EXPECT_EQ(mb, static_cast<int>(std::lround(1.0 / (o.grading - 1.0)))) << what;
      EXPECT_NEAR(lay.g_ball, o.grading, 0.05 * o.grading) << what;
      EXPECT_NEAR(lay.g_block[0], o.grading, 0.05 * o.grading) << what;
    }
    int boundary = 0;
    for (const auto& [name, cells] : m.cell_groups)
      if (name != "BALL" && name != "BLOCK") boundary += static_cast<int>(cells.size());
    EXPECT_EQ(m.n_cells(), static_cast<int>(group_size(m, "BALL") + group_size(m, "BLOCK")) + boundary) << what;
    for (const char* g : {"O_BALL", "O_BLOCK", "C_BALL", "D_BLOCK"}) ASSERT_EQ(m.node_groups.at(g).size(), 1u) << g;
  }
}

TEST(HertzMesh, CellCountsFollowTheLayout3d) {
  for (const auto& o : {opts(CellType::Hexa8, 30, 1.3), opts(CellType::Hexa20, 6, 1.0, 1.0, 1.0, 0.5)}) {
    tools::HertzLayout lay;
    const Mesh m = tools::make_hertz(o, &lay);
    const int mb = lay.m_ball, kb = lay.layers_ball;
    EXPECT_EQ(m.dim, 3);
    EXPECT_EQ(group_size(m, "BALL"), static_cast<size_t>(mb * mb * mb + 3 * mb * mb * kb));
    EXPECT_EQ(group_size(m, "BALL_SURF"), static_cast<size_t>(mb * mb + 2 * mb * kb));
    EXPECT_EQ(group_size(m, "SYMX_BALL"), static_cast<size_t>(mb * mb + 2 * mb * kb));
    EXPECT_EQ(group_size(m, "SYMY_BALL"), static_cast<size_t>(mb * mb + 2 * mb * kb));
    EXPECT_EQ(group_size(m, "BALL_TOP"), static_cast<size_t>(3 * mb * mb));
    const int mx = lay.m_block[0], mz = lay.m_block[2], kl = lay.layers_block;
    EXPECT_EQ(group_size(m, "BLOCK"), static_cast<size_t>(mx * mx * mz + kl * (mx * mx + 2 * mx * mz)));
    EXPECT_EQ(group_size(m, "BLOCK_TOP"), static_cast<size_t>(mx * mx + 2 * mx * kl));
    EXPECT_EQ(group_size(m, "BLOCK_BOTTOM"), static_cast<size_t>(mx * mx));
    EXPECT_EQ(group_size(m, "BLOCK_SIDE"), static_cast<size_t>(2 * mx * mz));
    if (o.grading == 1.0) {
      EXPECT_EQ(mz, 3);
    }
    for (const char* g : {"O_BALL", "O_BLOCK", "C_BALL", "D_BLOCK"}) ASSERT_EQ(m.node_groups.at(g).size(), 1u) << g;
  }
}

// Smallest scaled Jacobian over the nodes of every volume cell. Measured: 0.70 for every
// quadrilateral family (the 135 degree corners where a layer turns round the diagonal),
// 0.35 for triangles (the quadrilaterals cut along one diagonal), 0.57 for hexahedra.
TEST(HertzMesh, CellsArePositiveAndWellShaped) {
  struct Case {
    tools::HertzOptions o;
    double bound;
  };
  for (const Case& k : {Case{opts(CellType::Quad4, 50, 1.2), 0.65}, Case{opts(CellType::Quad8, 50, 1.2), 0.65},
                        Case{opts(CellType::Quad8, 10, 1.0), 0.65}, Case{opts(CellType::Quad4, 200, 1.1), 0.65},
                        Case{opts(CellType::Quad8, 20, 1.5), 0.65}, Case{opts(CellType::Tria6, 40, 1.25), 0.33},
                        Case{opts(CellType::Hexa8, 30, 1.3), 0.5}, Case{opts(CellType::Hexa20, 30, 1.3), 0.5},
                        Case{opts(CellType::Hexa20, 6, 1.0), 0.5}}) {
    Mesh m = tools::make_hertz(k.o);
    const std::string what = std::string(cell_info(k.o.type).name) + " N=" + std::to_string(k.o.n);
    EXPECT_TRUE(find_inverted_cells(m).empty()) << what;
    double worst = 1.0;
    for (int c = 0; c < m.n_cells(); ++c)
      if (cell_info(m.cell_types[c]).dim == m.dim) worst = std::min(worst, scaled_jacobian(m, c));
    EXPECT_GT(worst, k.bound) << what;
    // boundary cells point out of their body (ORIE_PEAU would change nothing)
    for (const auto& [name, cells] : m.cell_groups)
      if (name != "BALL" && name != "BLOCK") {
        EXPECT_EQ(orient_boundary_outward(m, cells), 0) << what << " " << name;
      }
  }
}

TEST(HertzMesh, GroupsLieOnTheirCurvesAndQuadraticEdgesOnTheSphere) {
  for (const auto& o : {opts(CellType::Quad8, 30, 1.25, 0.5, 1.0, 0.8), opts(CellType::Tria6, 8, 1.0, 2.0, 2.0, 2.0),
                        opts(CellType::Hexa20, 20, 1.4, 0.5, 0.6, 0.4)}) {
    const Mesh m = tools::make_hertz(o);
    const int up = m.dim - 1;  // the axis
    const double r = o.radius;
    const std::string what(cell_info(o.type).name);
    for (int n : m.nodes_of_cells(m.cell_groups.at("BALL_SURF"))) EXPECT_NEAR(from_centre(m, n, r), r, 1e-14 * r) << what;
    for (int n : m.nodes_of_cells(m.cell_groups.at("BALL_TOP"))) EXPECT_EQ(m.node(n)[up], r) << what;
    for (int n : m.nodes_of_cells(m.cell_groups.at("BLOCK_TOP"))) EXPECT_EQ(m.node(n)[up], 0.0) << what;
    for (int n : m.nodes_of_cells(m.cell_groups.at("BLOCK_BOTTOM"))) EXPECT_EQ(m.node(n)[up], -o.height) << what;
    for (int n : m.nodes_of_cells(m.cell_groups.at("BLOCK_SIDE")))
      EXPECT_TRUE(m.node(n)[0] == o.width || (m.dim == 3 && m.node(n)[1] == o.width)) << what;
    for (const char* g : {"AXIS_BALL", "AXIS_BLOCK", "SYMX_BALL", "SYMX_BLOCK"})
      if (m.cell_groups.count(g)) {
        for (int n : m.nodes_of_cells(m.cell_groups.at(g))) EXPECT_EQ(m.node(n)[0], 0.0) << g;
      }
    for (const char* g : {"SYMY_BALL", "SYMY_BLOCK"})
      if (m.cell_groups.count(g)) {
        for (int n : m.nodes_of_cells(m.cell_groups.at(g))) EXPECT_EQ(m.node(n)[1], 0.0) << g;
      }
    // every ball node inside the ball, every block node inside the block
    for (int n : m.nodes_of_cells(m.cell_groups.at("BALL"))) {
      EXPECT_LE(from_centre(m, n, r), r * (1 + 1e-14)) << what;
      EXPECT_LE(m.node(n)[up], r) << what;
    }
    for (int n : m.nodes_of_cells(m.cell_groups.at("BLOCK"))) EXPECT_LE(m.node(n)[up], 0.0) << what;
    // the contact point is O in both bodies, which share no node
    for (const char* g : {"O_BALL", "O_BLOCK"})
      for (int d = 0; d < 3; ++d) EXPECT_EQ(m.node(m.node_groups.at(g)[0])[d], 0.0) << g;
    EXPECT_NE(m.node_groups.at("O_BALL")[0], m.node_groups.at("O_BLOCK")[0]);
    EXPECT_EQ(m.node(m.node_groups.at("C_BALL")[0])[up], r);
    EXPECT_EQ(m.node(m.node_groups.at("D_BLOCK")[0])[up], -o.height);
    // curved: the mid-side nodes of the coarsest sphere faces stand off their chords
    double bulge = 0.0;
    for (int c : m.cell_groups.at("BALL_SURF")) bulge = std::max(bulge, testing::mid_side_offset(m, c));
    EXPECT_GT(bulge, 1e-3 * r) << what;
  }
}

TEST(HertzMesh, GradingGivesH0AtTheContactAndGrowthG) {
  for (const auto& o : {opts(CellType::Quad4, 100, 1.2), opts(CellType::Quad8, 400, 1.1, 2.0, 1.0, 1.0),
                        opts(CellType::Hexa8, 40, 1.25)}) {
    tools::HertzLayout lay;
    const Mesh m = tools::make_hertz(o, &lay);
    const std::string what = std::string(cell_info(o.type).name) + " N=" + std::to_string(o.n);
    EXPECT_DOUBLE_EQ(lay.h0, o.radius / o.n);
    // edge lengths along the contact line y = 0 (z = 0, y = 0 in 3D) of each body, from O outward
    const auto edges = [&](const std::string& g) {
      std::vector<double> xs;
      for (int n : m.nodes_of_cells(m.cell_groups.at(g)))
        if (m.dim == 2 || m.node(n)[1] == 0.0) xs.push_back(m.node(n)[0]);
      std::sort(xs.begin(), xs.end());
      xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
      std::vector<double> h;
      const int step = m.cell_n_nodes(m.cell_groups.at(g)[0]) > (m.dim == 2 ? 2 : 4) ? 2 : 1;  // skip mid nodes
      for (size_t i = step; i < xs.size(); i += step) h.push_back(xs[i] - xs[i - step]);
      return h;
    };
    const std::vector<double> top = edges("BLOCK_TOP");
    const std::vector<double> surf = edges("BALL_SURF");
    const int mcore = lay.m_block[0];
    for (int i = 0; i < mcore; ++i) EXPECT_NEAR(top[i], lay.h0, 1e-12) << what << " block core edge " << i;
    for (size_t i = mcore + 1; i < top.size(); ++i)
      EXPECT_NEAR(top[i] / top[i - 1], lay.g_block[0], 1e-9) << what << " block layer " << i;
    // the ball: x-extent of its contact edges is h0 at O, then grows by the layer ratio
    // (the conformal map is R x identity at O and shrinks cells by up to 2 towards the top)
    EXPECT_NEAR(surf[0], lay.h0, 0.01 * lay.h0) << what;
    for (size_t i = lay.m_ball + 1; i < surf.size() / 2; ++i)
      EXPECT_NEAR(surf[i] / surf[i - 1], lay.g_ball, 0.12 * lay.g_ball) << what << " ball layer " << i;
    // the growth actually achieved stays close to the G asked for
    EXPECT_NEAR(lay.g_block[0], o.grading, 0.04 * o.grading) << what;
    EXPECT_NEAR(lay.g_ball, o.grading, 0.04 * o.grading) << what;
  }
}

TEST(HertzMesh, AreaAndVolumeMatchTheExactGeometry) {
  // ball: quarter disc pi R^2 / 4, quarter of the lower half sphere pi R^3 / 6; block exact.
  // Straight-sided 2D cells miss exactly the circular segments under the chords of BALL_SURF;
  // quadratic cells follow the sphere to O(h^4); HEXA8 faces are bilinear patches between
  // nodes on the sphere (relative tolerances: measured 3.3e-6 (QUAD8, graded), 8.7e-8 (TRIA6, uniform), 2.1e-2 (HEXA8, coarse
  // cells near the top), 1.4e-4 (HEXA20)).
  struct Case {
    tools::HertzOptions o;
    double tol;  // relative, on the ball
  };
  for (const Case& k : {Case{opts(CellType::Quad4, 40, 1.2, 0.7, 1.0, 0.6), 1e-13}, Case{opts(CellType::Tria3, 9, 1.0), 1e-13},
                        Case{opts(CellType::Quad8, 40, 1.2, 0.7, 1.0, 0.6), 1e-5},
                        Case{opts(CellType::Tria6, 12, 1.0, 1.0, 1.0, 1.0), 1e-6}, Case{opts(CellType::Hexa8, 20, 1.3, 1.0, 1.2, 0.8), 2.5e-2},
                        Case{opts(CellType::Hexa20, 20, 1.3, 1.0, 1.2, 0.8), 2e-4}}) {
    const Mesh m = tools::make_hertz(k.o);
    const double r = k.o.radius, w = k.o.width, h = k.o.height;
    const std::string what(cell_info(k.o.type).name);
    double ball = m.dim == 2 ? M_PI * r * r / 4 : M_PI * r * r * r / 6;
    if (k.o.type == CellType::Quad4 || k.o.type == CellType::Tria3)
      for (int c : m.cell_groups.at("BALL_SURF")) {  // segment of angle a: R^2 (a - sin a) / 2
        const double* p = m.node(m.cell(c)[0]);
        const double* q = m.node(m.cell(c)[1]);
        const double a = 2 * std::asin(std::hypot(p[0] - q[0], p[1] - q[1]) / (2 * r));
        ball -= 0.5 * r * r * (a - std::sin(a));
      }
    const double block = m.dim == 2 ? w * h : w * w * h;
    EXPECT_NEAR(measure(m, "BALL") / ball, 1.0, k.tol) << what;
    EXPECT_LT(measure(m, "BALL"), ball * (1 + 1e-12)) << what;  // inscribed
    EXPECT_NEAR(measure(m, "BLOCK") / block, 1.0, 1e-12) << what;
  }
}

// --full: the half model mirrored about x = 0. Every cell of either kind positive, every
// boundary group facing out, the areas doubled, the axis nodes shared (one node per position),
// the axis groups gone.
TEST(HertzMesh, MirroredAboutTheAxisIsTheWholeSceneFacingOut) {
  for (CellType t : {CellType::Quad4, CellType::Quad8, CellType::Tria3, CellType::Tria6}) {
    const std::string what(cell_info(t).name);
    const Mesh half = tools::make_hertz(opts(t, 16, 1.2, 1.0, 1.0, 0.8));
    Mesh m = tools::mirrored_about_x0(half, 1e-9);
    int on_axis = 0;
    for (int i = 0; i < half.n_nodes(); ++i) on_axis += std::abs(half.node(i)[0]) <= 1e-9;
    EXPECT_EQ(m.n_nodes(), 2 * half.n_nodes() - on_axis) << what;
    EXPECT_TRUE(find_inverted_cells(m).empty()) << what;
    for (const char* group : {"BALL", "BLOCK"})
      EXPECT_NEAR(measure(m, group), 2.0 * measure(half, group), 1e-12 * measure(half, group)) << what << " " << group;
    for (const char* group : {"BALL_SURF", "BALL_TOP", "BLOCK_TOP", "BLOCK_BOTTOM", "BLOCK_SIDE"}) {
      EXPECT_EQ(m.cell_groups.at(group).size(), 2 * half.cell_groups.at(group).size()) << what << " " << group;
      std::vector<int> cells = m.cell_groups.at(group);
      EXPECT_EQ(orient_boundary_outward(m, cells), 0) << what << " " << group;
    }
    EXPECT_EQ(m.cell_groups.count("AXIS_BALL") + m.cell_groups.count("AXIS_BLOCK"), 0u) << what;
    // The axis nodes were not duplicated: the only shared position is still O (O_BALL, O_BLOCK:
    // the two bodies are meshed apart and touch there).
    const auto shared_positions = [](const Mesh& mesh) {
      std::vector<std::pair<double, double>> xy;
      for (int i = 0; i < mesh.n_nodes(); ++i) xy.emplace_back(mesh.node(i)[0], mesh.node(i)[1]);
      std::sort(xy.begin(), xy.end());
      int shared = 0;
      for (size_t i = 1; i < xy.size(); ++i) shared += xy[i] == xy[i - 1];
      return shared;
    };
    EXPECT_EQ(shared_positions(half), 1) << what;
    EXPECT_EQ(shared_positions(m), 1) << what;
  }
}

TEST(HertzMesh, MedRoundTripKeepsCoordinatesAndGroups) {
  testing::expect_med_round_trip(tools::make_hertz(opts(CellType::Quad8, 20, 1.3)), "hertz");
}

TEST(HertzMesh, RefusesBadInput) {
  EXPECT_THROW(tools::make_hertz(opts(CellType::Penta6, 10, 1.0)), DeckError);
  EXPECT_THROW(tools::make_hertz(opts(CellType::Quad4, 10, 0.9)), DeckError);
  EXPECT_THROW(tools::make_hertz(opts(CellType::Quad4, 10, 1.2, -1.0)), DeckError);
  EXPECT_THROW(tools::make_hertz(opts(CellType::Quad4, 0, 1.0)), DeckError);
  // the core of m = 10 cells of h0 = R/10 would fill the ball
  EXPECT_THROW(tools::make_hertz(opts(CellType::Quad4, 10, 1.1)), DeckError);
  // ... or the block
  EXPECT_THROW(tools::make_hertz(opts(CellType::Quad4, 100, 1.1, 1.0, 0.05, 1.0)), DeckError);
}

}  // namespace
}  // namespace lunaster::engine
