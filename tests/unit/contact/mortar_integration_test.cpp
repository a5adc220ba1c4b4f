// Mortar segmentation and dual basis: overlap measures, exact integration of products of slave
// and master shape functions against independent integrals, biorthogonality of the dual basis.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "engine/contact/integration_rules.hpp"
#include "engine/contact/mortar_integration.hpp"
#include "engine/contact/surface_element.hpp"

using namespace lunaster::engine;
using namespace lunaster::engine::contact;
namespace mortar = lunaster::engine::contact::mortar;

namespace {

using P2 = std::array<double, 2>;

// A flat plane in space: x = o + X e1 + Y e2 (e1, e2 orthonormal, normal e1 x e2 is no axis).
struct Frame {
  double o[3], e1[3], e2[3], e3[3];
  void map(double X, double Y, double h, double* x) const {
    for (int i = 0; i < 3; ++i) x[i] = o[i] + X * e1[i] + Y * e2[i] + h * e3[i];
  }
};

Frame rotated_plane() {
  return {{0.3, -1.2, 2.5}, {1.0 / 3, 2.0 / 3, 2.0 / 3}, {2.0 / 3, 1.0 / 3, -2.0 / 3}, {-2.0 / 3, 2.0 / 3, -1.0 / 3}};
}

// A line in the xy plane (2D problems): x = o + s d, normal (d_y, -d_x).
Frame rotated_line() {
  const double c = std::cos(0.7), s = std::sin(0.7);
  return {{0.4, -0.9, 0.0}, {c, s, 0.0}, {0.0, 0.0, 0.0}, {s, -c, 0.0}};
}

// A cell with its node coordinates in space (x) and in the plane's local frame (X, 2 per node).
struct Cell {
  CellType type;
  std::vector<double> x, X;
};

bool is_segment(CellType t) { return t == CellType::Seg2 || t == CellType::Seg3; }
bool is_quadratic(CellType t) { return t == CellType::Seg3 || t == CellType::Tria6 || t == CellType::Quad8; }

// Cell of type t on the vertices `v` (local coordinates, counter-clockwise), mid-edge nodes
// at the middle of straight edges plus an offset h(X, Y) along the plane normal (curved cells).
Cell make_cell(CellType t, const std::vector<P2>& v, const Frame& f,
               const std::function<double(double, double)>& h = nullptr) {
  Cell c{t, {}, {}};
  std::vector<P2> nodes = v;
  if (is_quadratic(t)) {
    const int nv = static_cast<int>(v.size());
    const int ne = nv == 2 ? 1 : nv;
    for (int e = 0; e < ne; ++e)
      nodes.push_back({0.5 * (v[e][0] + v[(e + 1) % nv][0]), 0.5 * (v[e][1] + v[(e + 1) % nv][1])});
  }
  for (const P2& p : nodes) {
    double x[3];
    f.map(p[0], p[1], h ? h(p[0], p[1]) : 0.0, x);
    c.x.insert(c.x.end(), x, x + 3);
    c.X.insert(c.X.end(), {p[0], p[1]});
  }
  return c;
}

// The same cell with the opposite orientation (a master facing the slave).
Cell reversed(const Cell& c) {
  static const int seg2[] = {1, 0}, seg3[] = {1, 0, 2}, tria3[] = {0, 2, 1}, tria6[] = {0, 2, 1, 5, 4, 3},
                   quad4[] = {0, 3, 2, 1}, quad8[] = {0, 3, 2, 1, 7, 6, 5, 4};
  const int* perm = c.type == CellType::Seg2    ? seg2
                    : c.type == CellType::Seg3  ? seg3
                    : c.type == CellType::Tria3 ? tria3
                    : c.type == CellType::Tria6 ? tria6
                    : c.type == CellType::Quad4 ? quad4
                                                : quad8;
  Cell r{c.type, {}, {}};
  for (int a = 0; a < surface_n_nodes(c.type); ++a) {
    r.x.insert(r.x.end(), c.x.begin() + 3 * perm[a], c.x.begin() + 3 * perm[a] + 3);
    r.X.insert(r.X.end(), c.X.begin() + 2 * perm[a], c.X.begin() + 2 * perm[a] + 2);
  }
  return r;
}

std::vector<Cell> reversed(const std::vector<Cell>& cells) {
  std::vector<Cell> r;
  for (const Cell& c : cells) r.push_back(reversed(c));
  return r;
}

// Cells of a structured n x n grid of [0,1]^2 whose nodes are moved by `warp` (QUAD: one
// cell per square; TRIA: two, diagonals alternating).
std::vector<Cell> grid(CellType t, int n, const std::function<P2(double, double)>& warp, const Frame& f,
                       const std::function<double(double, double)>& h = nullptr) {
  std::vector<Cell> cells;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const P2 a = warp(double(i) / n, double(j) / n), b = warp(double(i + 1) / n, double(j) / n);
      const P2 c = warp(double(i + 1) / n, double(j + 1) / n), d = warp(double(i) / n, double(j + 1) / n);
      if (!is_triangle(t)) {
        cells.push_back(make_cell(t, {a, b, c, d}, f, h));
      } else if ((i + j) % 2 == 0) {
        cells.push_back(make_cell(t, {a, b, c}, f, h)), cells.push_back(make_cell(t, {a, c, d}, f, h));
      } else {
        cells.push_back(make_cell(t, {a, b, d}, f, h)), cells.push_back(make_cell(t, {b, c, d}, f, h));
      }
    }
  return cells;
}

// Segments of [-1,1] at the parameters s (increasing).
std::vector<Cell> segments(CellType t, const std::vector<double>& s, const Frame& f,
                           const std::function<double(double, double)>& h = nullptr) {
  std::vector<Cell> cells;
  for (size_t k = 0; k + 1 < s.size(); ++k) cells.push_back(make_cell(t, {{s[k], 0.0}, {s[k + 1], 0.0}}, f, h));
  return cells;
}

std::vector<double> uniform(int n) {
  std::vector<double> s;
  for (int k = 0; k <= n; ++k) s.push_back(-1.0 + 2.0 * k / n);
  return s;
}

std::vector<double> graded(int n) {  // non-uniform, ends fixed
  std::vector<double> s;
  for (int k = 0; k <= n; ++k) {
    const double u = -1.0 + 2.0 * k / n;
    s.push_back(u + 0.15 * std::sin(M_PI * u));
  }
  return s;
}

P2 identity(double X, double Y) { return {X, Y}; }
P2 shear(double X, double Y) { return {1.3 * X + 0.4 * Y, -0.2 * X + 0.9 * Y}; }
// Non-affine warps that keep the unit square's boundary in place (cells stay convex).
P2 warp_a(double X, double Y) {
  const double b = X * (1 - X) * Y * (1 - Y);
  return {X + 0.6 * b, Y - 0.4 * b};
}
P2 warp_b(double X, double Y) {
  const double b = X * (1 - X) * Y * (1 - Y);
  return {X - 0.5 * b, Y + 0.7 * b};
}

// Measure of a flat straight-edged cell from its local vertex coordinates.
double local_measure(const Cell& c) {
  const int nv = surface_n_vertices(c.type);
  if (nv == 2) return std::abs(c.X[2] - c.X[0]);
  double s = 0.0;
  for (int a = 0; a < nv; ++a) {
    const int b = (a + 1) % nv;
    s += c.X[2 * a] * c.X[2 * b + 1] - c.X[2 * b] * c.X[2 * a + 1];
  }
  return 0.5 * std::abs(s);
}

// Reference coordinates of the local point (X, Y) on an affine cell (segment, triangle,
// parallelogram), from its vertex coordinates alone (independent of the code under test).
void local_to_xi(const Cell& c, double X, double Y, double* xi) {
  const double* v = c.X.data();
  xi[1] = 0.0;
  if (is_segment(c.type)) {
    xi[0] = (2.0 * X - v[0] - v[2]) / (v[2] - v[0]);
    return;
  }
  double a[2], b[2], r[2];
  if (is_triangle(c.type)) {
    a[0] = v[2] - v[0], a[1] = v[3] - v[1], b[0] = v[4] - v[0], b[1] = v[5] - v[1];
    r[0] = X - v[0], r[1] = Y - v[1];
  } else {
    for (int i = 0; i < 2; ++i) {
      a[i] = 0.25 * (-v[i] + v[2 + i] + v[4 + i] - v[6 + i]);
      b[i] = 0.25 * (-v[i] - v[2 + i] + v[4 + i] + v[6 + i]);
    }
    r[0] = X - 0.25 * (v[0] + v[2] + v[4] + v[6]), r[1] = Y - 0.25 * (v[1] + v[3] + v[5] + v[7]);
  }
  const double det = a[0] * b[1] - a[1] * b[0];
  xi[0] = (r[0] * b[1] - r[1] * b[0]) / det;
  xi[1] = (a[0] * r[1] - a[1] * r[0]) / det;
}

// Position of xi on a cell in space.
void position(const Cell& c, const double* xi, double* x) {
  const SurfacePoint p = surface_point(c.type, c.x.data(), xi);
  for (int i = 0; i < 3; ++i) x[i] = p.x[i];
}

double overlap(const Cell& s, const Cell& m, int degree, std::vector<mortar::OverlapPoint>& pts) {
  return mortar::overlap_points(s.type, s.x.data(), m.type, m.x.data(), degree, pts);
}

const CellType kSurfaces[] = {CellType::Seg2, CellType::Seg3, CellType::Tria3,
                              CellType::Tria6, CellType::Quad4, CellType::Quad8};

// A stretched parallelogram (or segment) in the rotated plane (line), area 2.01 (length 2.7).
Cell stretched_cell(CellType t) {
  if (is_segment(t)) return make_cell(t, {{-0.6, 0.0}, {2.1, 0.0}}, rotated_line());
  if (is_triangle(t)) return make_cell(t, {{0.0, 0.0}, {2.4, 0.3}, {0.5, 0.9}}, rotated_plane());
  return make_cell(t, {{0.0, 0.0}, {2.4, 0.3}, {2.9, 1.2}, {0.5, 0.9}}, rotated_plane());
}

// The stretched cell moved by (dX, dY) in its plane (line) and reversed: a master covering
// part of it.
Cell shifted_master(const Cell& s, double dX, double dY) {
  const Frame f = is_segment(s.type) ? rotated_line() : rotated_plane();
  std::vector<P2> v;
  for (int a = 0; a < surface_n_vertices(s.type); ++a) v.push_back({s.X[2 * a] + dX, s.X[2 * a + 1] + dY});
  return reversed(make_cell(s.type, v, f));
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Shape functions of the slave side.

TEST(MortarSlaveShape, TransformedFunctionsSumToOneAndKeepVertexValues) {
  for (CellType t : kSurfaces) {
    EXPECT_EQ(mortar::transformed_slave(t), t == CellType::Tria6 || t == CellType::Quad8);
    const int nn = surface_n_nodes(t);
    const double pts[][2] = {{0.1, 0.2}, {0.3, 0.05}, {-0.7, 0.6}, {0.45, 0.45}};
    for (const auto& xi : pts) {
      double n[8], plain[8];
      mortar::slave_shape(t, xi, n);
      surface_shape(t, xi, plain, nullptr, nullptr);
      double sum = 0.0;
      for (int a = 0; a < nn; ++a) sum += n[a];
      EXPECT_NEAR(sum, 1.0, 1e-15) << surface_type_name(t);
      if (!mortar::transformed_slave(t)) {
        for (int a = 0; a < nn; ++a) EXPECT_EQ(n[a], plain[a]);
      }
    }
    // N~_a at node b: a vertex keeps 1 at itself; a mid-edge node carries 1 - 2 alpha of
    // itself and alpha to each vertex of its edge.
    for (int b = 0; b < nn; ++b) {
      double xi[2], n[8];
      surface_reference_node(t, b, xi);
      mortar::slave_shape(t, xi, n);
      int v1 = -1, v2 = -1;
      const bool mid = mortar::edge_vertices(t, b, &v1, &v2);
      for (int a = 0; a < nn; ++a) {
        double expected = a == b ? 1.0 : 0.0;
        if (mortar::transformed_slave(t) && mid)
          expected = a == b ? 1.0 - 2 * mortar::kQuadraticAlpha : (a == v1 || a == v2) ? mortar::kQuadraticAlpha : 0.0;
        EXPECT_NEAR(n[a], expected, 1e-15) << surface_type_name(t) << " node " << b << " function " << a;
      }
    }
  }
}

TEST(MortarSlaveShape, EdgeVertices) {
  int v1 = -1, v2 = -1;
  EXPECT_FALSE(mortar::edge_vertices(CellType::Seg2, 1, &v1, &v2));
  EXPECT_FALSE(mortar::edge_vertices(CellType::Quad8, 3, &v1, &v2));
  EXPECT_FALSE(mortar::edge_vertices(CellType::Quad4, 3, &v1, &v2));
  ASSERT_TRUE(mortar::edge_vertices(CellType::Seg3, 2, &v1, &v2));
  EXPECT_EQ(v1, 0);
  EXPECT_EQ(v2, 1);
  const int tria6[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (int m = 3; m < 6; ++m) {
    ASSERT_TRUE(mortar::edge_vertices(CellType::Tria6, m, &v1, &v2));
    EXPECT_EQ(v1, tria6[m - 3][0]);
    EXPECT_EQ(v2, tria6[m - 3][1]);
  }
  const int quad8[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  for (int m = 4; m < 8; ++m) {
    ASSERT_TRUE(mortar::edge_vertices(CellType::Quad8, m, &v1, &v2));
    EXPECT_EQ(v1, quad8[m - 4][0]);
    EXPECT_EQ(v2, quad8[m - 4][1]);
  }
}

// ---------------------------------------------------------------------------------------
// Single pairs: matching, not facing, disjoint.

TEST(MortarOverlap, MatchingPairGivesTheWholeCellAndTheSamePoints) {
  for (CellType t : kSurfaces) {
    const Cell s = stretched_cell(t), m = reversed(s);
    std::vector<mortar::OverlapPoint> pts;
    const double measure = overlap(s, m, 4, pts);
    const double expected = local_measure(s);
    EXPECT_NEAR(measure, expected, 1e-14 * expected) << surface_type_name(t);
    double sum = 0.0;
    for (const auto& p : pts) {
      sum += p.w;
      double xs[3], xm[3];
      position(s, p.xi_s, xs), position(m, p.xi_m, xm);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(xs[i], xm[i], 1e-14 * 3) << surface_type_name(t);
      EXPECT_LE(outside_distance(t, p.xi_s), 1e-14);
      EXPECT_LE(outside_distance(t, p.xi_m), 1e-14);
    }
    EXPECT_NEAR(sum, measure, 1e-15 * expected);
    // Points per integration cell: 2D Gauss with 3 points; 3D the 6-point degree-4 triangle
    // rule on the fan triangles of the vertex polygon (3 or 4 triangles).
    const size_t n_expected = is_segment(t) ? 3 : is_triangle(t) ? 18 : 24;
    EXPECT_EQ(pts.size(), n_expected) << surface_type_name(t);
  }
}

TEST(MortarOverlap, CellsNotFacingOrDisjointGiveNothing) {
  for (CellType t : kSurfaces) {
    const Cell s = stretched_cell(t);
    std::vector<mortar::OverlapPoint> pts(3);  // existing content must stay as is
    pts[1].w = 7.0;
    EXPECT_EQ(overlap(s, s, 3, pts), 0.0) << surface_type_name(t);  // same orientation: not facing
    EXPECT_EQ(overlap(s, shifted_master(s, 3.5, 0.0), 3, pts), 0.0) << surface_type_name(t);
    if (!is_segment(t)) {
      EXPECT_EQ(overlap(s, shifted_master(s, 0.0, -1.3), 3, pts), 0.0) << surface_type_name(t);
      // Touching along an edge only (neighbour cell of the matching mesh).
      EXPECT_EQ(overlap(s, shifted_master(s, 0.5, 0.9), 3, pts), 0.0) << surface_type_name(t);
    } else {
      EXPECT_EQ(overlap(s, shifted_master(s, 2.7, 0.0), 3, pts), 0.0);  // touching at an end
    }
    ASSERT_EQ(pts.size(), 3u);
    EXPECT_EQ(pts[1].w, 7.0);
  }
}

TEST(MortarOverlap, PartialOverlapOfShiftedCells) {
  // The master is the slave moved within the plane: the overlap of two translated
  // parallelograms (triangles) is known in closed form through the local frame.
  for (CellType t : kSurfaces) {
    const Cell s = stretched_cell(t);
    std::vector<mortar::OverlapPoint> pts;
    if (is_segment(t)) {
      EXPECT_NEAR(overlap(s, shifted_master(s, 0.8, 0.0), 3, pts), 2.7 - 0.8, 1e-14);
      continue;
    }
    // Parallelogram with edges a = (2.4, 0.3), b = (0.5, 0.9) (area 2.01) moved by (0.6, 0) =
    // alpha a + beta b, alpha = 0.54/2.01, beta = -0.18/2.01: the overlap is (1 - |alpha|)
    // (1 - |beta|) of the cell.
    if (!is_triangle(t)) {
      const double alpha = 0.54 / 2.01, beta = 0.18 / 2.01;
      const double expected = (1 - alpha) * (1 - beta) * local_measure(s);
      EXPECT_NEAR(overlap(s, shifted_master(s, 0.6, 0.0), 4, pts), expected, 1e-14 * expected) << surface_type_name(t);
    } else {
      // Translate along the edge from vertex 0 to vertex 1 by 30 %: the overlap is the
      // triangle scaled by 0.7 (area 0.49 of the cell).
      const double expected = 0.49 * local_measure(s);
      EXPECT_NEAR(overlap(s, shifted_master(s, 0.72, 0.09), 4, pts), expected, 1e-14 * expected)
          << surface_type_name(t);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Non-matching surfaces: overlap measures add up to each slave cell.

namespace {

void expect_tiling(const std::vector<Cell>& slaves, const std::vector<Cell>& masters, int degree, const char* what) {
  for (size_t k = 0; k < slaves.size(); ++k) {
    double total = 0.0;
    int n_touching = 0;
    for (const Cell& m : masters) {
      std::vector<mortar::OverlapPoint> pts;
      const double measure = overlap(slaves[k], m, degree, pts);
      double sum = 0.0;
      for (const auto& p : pts) sum += p.w;
      EXPECT_NEAR(sum, measure, 1e-15 * local_measure(slaves[k]));
      EXPECT_EQ(measure == 0.0, pts.empty());
      total += measure;
      n_touching += measure > 0.0;
    }
    const double expected = local_measure(slaves[k]);
    EXPECT_NEAR(total, expected, 1e-13 * expected) << what << " slave cell " << k;
    EXPECT_GE(n_touching, 1);
  }
}

}  // namespace

TEST(MortarOverlap, RoundingLevelPerturbationsOfSharedEdgesChangeNothing) {
  // Matching cells whose master nodes are moved by 1e-14 (any direction): the clip polygon
  // keeps its vertices (no spurious intersection points near the shared edges), so the fan,
  // the number of points and the points themselves stay put; the neighbour across an edge,
  // now overlapping by a 1e-14 sliver, still gives nothing.
  for (CellType t : {CellType::Tria3, CellType::Quad4, CellType::Tria6, CellType::Quad8}) {
    const Cell s = stretched_cell(t);
    auto perturb = [](Cell c) {
      for (size_t k = 0; k < c.x.size(); ++k) c.x[k] += (k % 3 == 1 ? -1e-14 : 1e-14) * double(1 + k % 4);
      return c;
    };
    std::vector<mortar::OverlapPoint> exact, moved, sliver;
    overlap(s, reversed(s), 4, exact);
    const double measure = overlap(s, perturb(reversed(s)), 4, moved);
    EXPECT_NEAR(measure, local_measure(s), 1e-13 * local_measure(s)) << surface_type_name(t);
    ASSERT_EQ(moved.size(), exact.size()) << surface_type_name(t);
    for (size_t k = 0; k < exact.size(); ++k) {
      EXPECT_NEAR(moved[k].w, exact[k].w, 1e-12 * local_measure(s));
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(moved[k].xi_s[i], exact[k].xi_s[i], 1e-12) << surface_type_name(t);
        EXPECT_NEAR(moved[k].xi_m[i], exact[k].xi_m[i], 1e-12) << surface_type_name(t);
      }
    }
    EXPECT_EQ(overlap(s, perturb(shifted_master(s, 0.5, 0.9 - 1e-14)), 4, sliver), 0.0) << surface_type_name(t);
    EXPECT_TRUE(sliver.empty());
  }
}

TEST(MortarOverlap, MillimetreCellsTileLikeMetreCells) {
  // Every tolerance is relative to the cell size: the same meshes scaled by 1e-3.
  Frame f = rotated_plane();
  for (double& c : f.o) c *= 1e-3;
  auto small = [](const std::function<P2(double, double)>& w) {
    return [w](double X, double Y) {
      const P2 p = w(X, Y);
      return P2{1e-3 * p[0], 1e-3 * p[1]};
    };
  };
  expect_tiling(grid(CellType::Quad4, 5, small(warp_a), f), reversed(grid(CellType::Tria6, 4, small(warp_b), f)), 2,
                "mm QUAD4 5x5 / TRIA6 4x4");
}

TEST(MortarOverlap, NonMatchingFacesTileEverySlaveCell) {
  const Frame f = rotated_plane();
  expect_tiling(grid(CellType::Quad4, 5, warp_a, f), reversed(grid(CellType::Quad8, 4, warp_b, f)), 2,
                "QUAD4 5x5 / QUAD8 4x4");
  expect_tiling(grid(CellType::Tria3, 4, warp_a, f), reversed(grid(CellType::Quad4, 3, warp_b, f)), 2,
                "TRIA3 4x4 / QUAD4 3x3");
  expect_tiling(grid(CellType::Tria6, 3, warp_b, f), reversed(grid(CellType::Quad8, 4, warp_a, f)), 4,
                "TRIA6 3x3 / QUAD8 4x4");
  expect_tiling(grid(CellType::Quad8, 4, warp_b, f), reversed(grid(CellType::Tria6, 5, warp_a, f)), 4,
                "QUAD8 4x4 / TRIA6 5x5");
  expect_tiling(grid(CellType::Quad4, 4, identity, f), reversed(grid(CellType::Tria3, 6, identity, f)), 2,
                "QUAD4 4x4 / TRIA3 6x6 (common grid lines)");
  // Matching meshes: every slave cell is covered by its own reversed copy only; neighbours
  // touch along edges or at vertices and must give exactly nothing.
  for (CellType t : {CellType::Tria3, CellType::Quad8}) {
    const std::vector<Cell> s = grid(t, 3, warp_a, f), m = reversed(s);
    expect_tiling(s, m, 2, "matching");
    for (size_t k = 0; k < s.size(); ++k)
      for (size_t l = 0; l < m.size(); ++l) {
        std::vector<mortar::OverlapPoint> pts;
        if (l != k) {
          EXPECT_EQ(overlap(s[k], m[l], 2, pts), 0.0) << k << " " << l;
        }
      }
  }
}

TEST(MortarOverlap, NonMatchingSegmentsTileEverySlaveCell) {
  const Frame f = rotated_line();
  expect_tiling(segments(CellType::Seg2, graded(12), f), reversed(segments(CellType::Seg3, uniform(11), f)), 3,
                "12 SEG2 / 11 SEG3");
  expect_tiling(segments(CellType::Seg3, uniform(7), f), reversed(segments(CellType::Seg2, graded(9), f)), 3,
                "7 SEG3 / 9 SEG2");
  expect_tiling(segments(CellType::Seg2, uniform(6), f), reversed(segments(CellType::Seg2, uniform(6), f)), 1,
                "matching SEG2");
}

TEST(MortarOverlap, CurvedMastersTileAFlatSlaveAlongItsNormal) {
  // Masters off the plane with their mid-edge nodes moved along the normal (curved cells):
  // their vertex polygons still tile the plane, and every master point lies on the line
  // through the slave point along the slave normal.
  const Frame f = rotated_plane();
  auto bump = [](double X, double Y) { return 0.15 + 0.08 * std::sin(3 * X + 2 * Y); };
  for (CellType mt : {CellType::Tria6, CellType::Quad8}) {
    const std::vector<Cell> slaves = grid(CellType::Quad4, 3, identity, f);
    const std::vector<Cell> masters = reversed(grid(mt, 4, warp_a, f, bump));
    expect_tiling(slaves, masters, 4, surface_type_name(mt));
    for (const Cell& s : slaves)
      for (const Cell& m : masters) {
        std::vector<mortar::OverlapPoint> pts;
        overlap(s, m, 4, pts);
        for (const auto& p : pts) {
          double xs[3], xm[3];
          position(s, p.xi_s, xs), position(m, p.xi_m, xm);
          const double d[3] = {xm[0] - xs[0], xm[1] - xs[1], xm[2] - xs[2]};
          const double tangential = std::abs(d[0] * f.e1[0] + d[1] * f.e1[1] + d[2] * f.e1[2]) +
                                    std::abs(d[0] * f.e2[0] + d[1] * f.e2[1] + d[2] * f.e2[2]);
          EXPECT_LE(tangential, 1e-14);
          EXPECT_GT(d[0] * f.e3[0] + d[1] * f.e3[1] + d[2] * f.e3[2], 0.05);  // the gap
        }
      }
  }
  // 2D: a curved SEG3 master line.
  const Frame l = rotated_line();
  auto arc = [](double X, double) { return 0.1 + 0.2 * X * X; };
  const std::vector<Cell> slaves = segments(CellType::Seg2, graded(8), l);
  const std::vector<Cell> masters = reversed(segments(CellType::Seg3, uniform(5), l, arc));
  expect_tiling(slaves, masters, 5, "SEG2 / curved SEG3");
  for (const Cell& s : slaves)
    for (const Cell& m : masters) {
      std::vector<mortar::OverlapPoint> pts;
      overlap(s, m, 5, pts);
      for (const auto& p : pts) {
        double xs[3], xm[3];
        position(s, p.xi_s, xs), position(m, p.xi_m, xm);
        const double d[3] = {xm[0] - xs[0], xm[1] - xs[1], xm[2] - xs[2]};
        EXPECT_LE(std::abs(d[0] * l.e1[0] + d[1] * l.e1[1]), 1e-14);
      }
    }
}

TEST(MortarOverlap, CurvedSlaveSegmentsAreSplitWhereTheMasterEndsProject) {
  // Curved SEG3 slave cells (a parabola), straight masters beside them: every master point
  // lies on the slave normal line of its slave point, and the pieces of each slave cell add
  // up to its arc length (6-point Gauss per piece against 400 pieces of 6-point Gauss: the
  // arc-length integrand is smooth, so both agree to rounding).
  const Frame l = rotated_line();
  auto arc = [](double X, double) { return 0.2 * X * X; };
  const std::vector<Cell> slaves = segments(CellType::Seg3, uniform(4), l, arc);
  Frame above = l;  // the same line moved by 0.3 along its normal, beyond the curve
  for (int i = 0; i < 3; ++i) above.o[i] += 0.3 * l.e3[i];
  const std::vector<Cell> masters = reversed(segments(CellType::Seg2, graded(7), above));
  const auto gauss = contact_integration_rule(CellType::Seg2, IntegrationScheme::Gauss, 6);
  for (const Cell& s : slaves) {
    double reference = 0.0;
    const int pieces = 400;
    for (int k = 0; k < pieces; ++k)
      for (const auto& g : gauss) {
        const double xi[2] = {-1.0 + (2.0 * k + 1.0 + g.xi[0]) / pieces, 0.0};
        reference += g.weight / pieces * surface_point(CellType::Seg3, s.x.data(), xi).jacobian;
      }
    double total = 0.0;
    for (const Cell& m : masters) {
      std::vector<mortar::OverlapPoint> pts;
      total += overlap(s, m, 11, pts);
      for (const auto& p : pts) {
        const SurfacePoint sp = surface_point(CellType::Seg3, s.x.data(), p.xi_s);
        double xm[3];
        position(m, p.xi_m, xm);
        const double d[3] = {xm[0] - sp.x[0], xm[1] - sp.x[1], xm[2] - sp.x[2]};
        EXPECT_LE(std::abs(d[0] * sp.t[0][0] + d[1] * sp.t[0][1]), 1e-14);
        EXPECT_GT(d[0] * sp.n[0] + d[1] * sp.n[1], 0.05);
      }
    }
    EXPECT_NEAR(total, reference, 1e-13 * reference);
  }
}

// ---------------------------------------------------------------------------------------
// Exact integration of products of slave and master shape functions.

TEST(MortarIntegration, AlignedRectanglesMatchTensorGaussOnTheOverlap) {
  // Rectangle grids of different spacings in a rotated plane: the overlap of two cells is the
  // rectangle [max, min] x [max, min], integrated here by a 6 x 6 Gauss rule and the affine
  // inverse maps of both cells (no clipping, no Newton).
  const Frame f = rotated_plane();
  const auto gauss = contact_integration_rule(CellType::Seg2, IntegrationScheme::Gauss, 6);
  auto stretch_s = [](double X, double Y) { return P2{2.0 * X + 0.3 * X * X, 0.7 * Y + 0.2 * Y * Y}; };
  auto stretch_m = [](double X, double Y) {
    return P2{2.0 * X + 0.3 * X * X - 0.1 * X * (1 - X), 0.7 * Y + 0.2 * Y * Y};
  };
  // Mapping each grid line (not the interior point) keeps the cells rectangles.
  auto rect_grid = [&](CellType t, int nx, int ny, const std::function<P2(double, double)>& g) {
    std::vector<Cell> cells;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double x0 = g(double(i) / nx, 0)[0], x1 = g(double(i + 1) / nx, 0)[0];
        const double y0 = g(0, double(j) / ny)[1], y1 = g(0, double(j + 1) / ny)[1];
        cells.push_back(make_cell(t, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, f));
      }
    return cells;
  };
  for (CellType st : {CellType::Quad4, CellType::Quad8})
    for (CellType mt : {CellType::Quad4, CellType::Quad8}) {
      const std::vector<Cell> slaves = rect_grid(st, 5, 4, stretch_s);
      const std::vector<Cell> masters = reversed(rect_grid(mt, 3, 5, stretch_m));
      const int ns = surface_n_nodes(st), nm = surface_n_nodes(mt);
      int n_pairs = 0;
      for (const Cell& s : slaves)
        for (const Cell& m : masters) {
          double lo[2], hi[2];
          for (int k = 0; k < 2; ++k) {
            lo[k] = std::max(std::min(s.X[k], s.X[4 + k]), std::min(m.X[k], m.X[4 + k]));
            hi[k] = std::min(std::max(s.X[k], s.X[4 + k]), std::max(m.X[k], m.X[4 + k]));
          }
          std::vector<double> expected(ns * nm, 0.0), computed(ns * nm, 0.0);
          if (hi[0] > lo[0] && hi[1] > lo[1])
            for (const auto& gx : gauss)
              for (const auto& gy : gauss) {
                const double X = 0.5 * (lo[0] + hi[0]) + 0.5 * (hi[0] - lo[0]) * gx.xi[0];
                const double Y = 0.5 * (lo[1] + hi[1]) + 0.5 * (hi[1] - lo[1]) * gy.xi[0];
                const double w = gx.weight * gy.weight * 0.25 * (hi[0] - lo[0]) * (hi[1] - lo[1]);
                double xs[2], xm[2], ns_[8], nm_[8];
                local_to_xi(s, X, Y, xs), local_to_xi(m, X, Y, xm);
                surface_shape(st, xs, ns_, nullptr, nullptr), surface_shape(mt, xm, nm_, nullptr, nullptr);
                for (int i = 0; i < ns; ++i)
                  for (int j = 0; j < nm; ++j) expected[i * nm + j] += w * ns_[i] * nm_[j];
              }
          std::vector<mortar::OverlapPoint> pts;
          overlap(s, m, 6, pts);
          for (const auto& p : pts) {
            double ns_[8], nm_[8];
            surface_shape(st, p.xi_s, ns_, nullptr, nullptr), surface_shape(mt, p.xi_m, nm_, nullptr, nullptr);
            for (int i = 0; i < ns; ++i)
              for (int j = 0; j < nm; ++j) computed[i * nm + j] += p.w * ns_[i] * nm_[j];
          }
          n_pairs += !pts.empty();
          EXPECT_EQ(pts.empty(), !(hi[0] > lo[0] && hi[1] > lo[1]));
          for (int k = 0; k < ns * nm; ++k)
            EXPECT_NEAR(computed[k], expected[k], 1e-12 * local_measure(s))
                << surface_type_name(st) << "/" << surface_type_name(mt) << " entry " << k;
        }
      EXPECT_GT(n_pairs, 20);
    }
}

TEST(MortarIntegration, MasterInterpolatedFieldMatchesSlaveIntegral) {
  // Parallelogram grids in a rotated plane: for a field f the master interpolates exactly
  // (linear on TRIA3/QUAD4, quadratic on TRIA6/QUAD8), sum over masters and points of
  // w N_i(xi_s) f_h(xi_m) must equal the integral of N_i f over the slave cell, computed
  // with the slave's own Gauss rule (no master, no clipping).
  const Frame f = rotated_plane();
  auto field = [](double X, double Y, bool quadratic) {
    const double lin = 1.0 + 0.3 * X - 0.7 * Y;
    return quadratic ? lin + 0.5 * X * X - 0.8 * X * Y + 0.25 * Y * Y : lin;
  };
  struct Case { CellType st; int ns; CellType mt; int nm; };
  const Case cases[] = {{CellType::Quad4, 5, CellType::Quad8, 4}, {CellType::Tria3, 4, CellType::Quad4, 3},
                        {CellType::Tria6, 3, CellType::Quad8, 4}, {CellType::Quad8, 3, CellType::Tria6, 4},
                        {CellType::Quad4, 4, CellType::Tria3, 5}, {CellType::Tria6, 4, CellType::Tria6, 3}};
  for (const Case& c : cases) {
    const bool quadratic = is_quadratic(c.mt);
    const std::vector<Cell> slaves = grid(c.st, c.ns, shear, f);
    const std::vector<Cell> masters = reversed(grid(c.mt, c.nm, shear, f));
    const auto rule = contact_integration_rule(c.st, IntegrationScheme::Gauss, 6);
    const int ns = surface_n_nodes(c.st), nm = surface_n_nodes(c.mt);
    for (const Cell& s : slaves) {
      double expected[8] = {}, computed[8] = {};
      for (const auto& q : rule) {
        double n[8], dn[16];
        surface_shape(c.st, q.xi, n, dn, nullptr);
        double X = 0, Y = 0, j[2][2] = {{0, 0}, {0, 0}};
        for (int a = 0; a < ns; ++a) {
          X += n[a] * s.X[2 * a], Y += n[a] * s.X[2 * a + 1];
          for (int r = 0; r < 2; ++r)
            for (int k = 0; k < 2; ++k) j[r][k] += dn[2 * a + k] * s.X[2 * a + r];
        }
        const double jac = std::abs(j[0][0] * j[1][1] - j[0][1] * j[1][0]);
        for (int a = 0; a < ns; ++a) expected[a] += q.weight * jac * n[a] * field(X, Y, quadratic);
      }
      for (const Cell& m : masters) {
        std::vector<mortar::OverlapPoint> pts;
        overlap(s, m, 6, pts);
        for (const auto& p : pts) {
          double n[8], nmv[8], fh = 0.0;
          surface_shape(c.st, p.xi_s, n, nullptr, nullptr), surface_shape(c.mt, p.xi_m, nmv, nullptr, nullptr);
          for (int l = 0; l < nm; ++l) fh += nmv[l] * field(m.X[2 * l], m.X[2 * l + 1], quadratic);
          for (int a = 0; a < ns; ++a) computed[a] += p.w * n[a] * fh;
        }
      }
      for (int a = 0; a < ns; ++a)
        EXPECT_NEAR(computed[a], expected[a], 1e-12 * local_measure(s))
            << surface_type_name(c.st) << "/" << surface_type_name(c.mt) << " node " << a;
    }
  }
}

TEST(MortarIntegration, SegmentsMatchGaussOnTheOverlapInterval) {
  // Straight segments on a rotated line: the overlap of two cells is [max, min] of their
  // parameter ranges, integrated by 6-point Gauss with the affine inverse maps.
  const Frame l = rotated_line();
  const auto gauss = contact_integration_rule(CellType::Seg2, IntegrationScheme::Gauss, 6);
  for (CellType st : {CellType::Seg2, CellType::Seg3})
    for (CellType mt : {CellType::Seg2, CellType::Seg3}) {
      const std::vector<Cell> slaves = segments(st, graded(12), l);
      const std::vector<Cell> masters = reversed(segments(mt, uniform(11), l));
      const int ns = surface_n_nodes(st), nm = surface_n_nodes(mt);
      for (const Cell& s : slaves)
        for (const Cell& m : masters) {
          const double lo = std::max(std::min(s.X[0], s.X[2]), std::min(m.X[0], m.X[2]));
          const double hi = std::min(std::max(s.X[0], s.X[2]), std::max(m.X[0], m.X[2]));
          std::vector<double> expected(ns * nm, 0.0), computed(ns * nm, 0.0);
          if (hi > lo)
            for (const auto& g : gauss) {
              const double X = 0.5 * (lo + hi) + 0.5 * (hi - lo) * g.xi[0], w = 0.5 * (hi - lo) * g.weight;
              double xs[2], xm[2], a[3], b[3];
              local_to_xi(s, X, 0, xs), local_to_xi(m, X, 0, xm);
              surface_shape(st, xs, a, nullptr, nullptr), surface_shape(mt, xm, b, nullptr, nullptr);
              for (int i = 0; i < ns; ++i)
                for (int j = 0; j < nm; ++j) expected[i * nm + j] += w * a[i] * b[j];
            }
          std::vector<mortar::OverlapPoint> pts;
          overlap(s, m, 4, pts);
          EXPECT_EQ(pts.empty(), !(hi > lo));
          for (const auto& p : pts) {
            double a[3], b[3];
            surface_shape(st, p.xi_s, a, nullptr, nullptr), surface_shape(mt, p.xi_m, b, nullptr, nullptr);
            for (int i = 0; i < ns; ++i)
              for (int j = 0; j < nm; ++j) computed[i * nm + j] += p.w * a[i] * b[j];
          }
          for (int k = 0; k < ns * nm; ++k)
            EXPECT_NEAR(computed[k], expected[k], 1e-12 * local_measure(s))
                << surface_type_name(st) << "/" << surface_type_name(mt) << " entry " << k;
        }
    }
}

// ---------------------------------------------------------------------------------------
// Dual basis.

namespace {

// Checks sum_p w Phi_i N~_j = delta_ij De_ii, sum_i Phi_i = 1 at the points, and returns De.
std::vector<double> expect_biorthogonal(CellType t, const std::vector<mortar::OverlapPoint>& pts, double measure) {
  const int nn = surface_n_nodes(t);
  std::vector<double> a(nn * nn, 0.0);
  EXPECT_TRUE(mortar::dual_coefficients(t, pts, a.data())) << surface_type_name(t);
  std::vector<double> de(nn, 0.0), prod(nn * nn, 0.0);
  for (const auto& p : pts) {
    double n[8], phi[8] = {};
    mortar::slave_shape(t, p.xi_s, n);
    double sum_phi = 0.0;
    for (int i = 0; i < nn; ++i) {
      for (int j = 0; j < nn; ++j) phi[i] += a[i * nn + j] * n[j];
      sum_phi += phi[i];
      de[i] += p.w * n[i];
    }
    EXPECT_NEAR(sum_phi, 1.0, 1e-13) << surface_type_name(t);
    for (int i = 0; i < nn; ++i)
      for (int j = 0; j < nn; ++j) prod[i * nn + j] += p.w * phi[i] * n[j];
  }
  for (int i = 0; i < nn; ++i)
    for (int j = 0; j < nn; ++j)
      EXPECT_NEAR(prod[i * nn + j], i == j ? de[i] : 0.0, 1e-13 * measure)
          << surface_type_name(t) << " " << i << " " << j;
  return de;
}

}  // namespace

TEST(MortarDualBasis, BiorthogonalOnAFullStretchedCell) {
  for (CellType t : kSurfaces) {
    const Cell s = stretched_cell(t);
    std::vector<mortar::OverlapPoint> pts;
    const double measure = overlap(s, reversed(s), 6, pts);
    ASSERT_NEAR(measure, local_measure(s), 1e-14 * measure);
    const std::vector<double> de = expect_biorthogonal(t, pts, measure);
    // Integrals of the (transformed) shape functions on an affine cell.
    std::vector<double> share;
    switch (t) {
      case CellType::Seg2: share = {0.5, 0.5}; break;
      case CellType::Seg3: share = {1.0 / 6, 1.0 / 6, 2.0 / 3}; break;
      case CellType::Tria3: share = {1.0 / 3, 1.0 / 3, 1.0 / 3}; break;
      case CellType::Quad4: share = {0.25, 0.25, 0.25, 0.25}; break;
      case CellType::Tria6: share = {2.0 / 15, 2.0 / 15, 2.0 / 15, 0.2, 0.2, 0.2}; break;  // alpha = 1/5
      default: share = {0.05, 0.05, 0.05, 0.05, 0.2, 0.2, 0.2, 0.2}; break;             // QUAD8
    }
    for (size_t i = 0; i < share.size(); ++i) {
      EXPECT_NEAR(de[i], share[i] * measure, 1e-14 * measure) << surface_type_name(t) << " node " << i;
      EXPECT_GT(de[i], 0.0);
    }
  }
  // Known dual bases of the linear cells (affine): Phi_1 = 2 N_1 - N_2 on SEG2, 3 N_1 - N_2
  // - N_3 on TRIA3, 4 N_1 - 2 N_2 + N_3 - 2 N_4 on QUAD4 (the tensor product of SEG2's).
  const std::vector<std::pair<CellType, std::vector<double>>> known = {
      {CellType::Seg2, {2, -1, -1, 2}},
      {CellType::Tria3, {3, -1, -1, -1, 3, -1, -1, -1, 3}},
      {CellType::Quad4, {4, -2, 1, -2, -2, 4, -2, 1, 1, -2, 4, -2, -2, 1, -2, 4}}};
  for (const auto& [t, expected] : known) {
    const Cell s = stretched_cell(t);
    std::vector<mortar::OverlapPoint> pts;
    overlap(s, reversed(s), 4, pts);  // QUAD4 products N_i N_j are of degree 4
    std::vector<double> a(expected.size());
    ASSERT_TRUE(mortar::dual_coefficients(t, pts, a.data()));
    for (size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], expected[k], 1e-13) << surface_type_name(t) << " " << k;
  }
}

TEST(MortarDualBasis, BiorthogonalOnAPartiallyCoveredCell) {
  // Only the part of the slave under the master is integrated: the coefficients are built
  // on that part (Cichosz and Bischoff) and are biorthogonal there.
  for (CellType t : kSurfaces) {
    const Cell s = stretched_cell(t);
    // SEG3 and QUAD8: shorter shifts, so that every De_ii stays positive (a QUAD8 corner
    // function has a negative integral on most partial coverages, even transformed: see
    // RefusesTooSmallCoverage).
    const Cell m = t == CellType::Seg3    ? shifted_master(s, 0.3, 0.0)
                   : t == CellType::Quad8 ? shifted_master(s, 0.2, 0.1)
                   : is_segment(t)        ? shifted_master(s, 1.1, 0.0)
                                          : shifted_master(s, 0.9, 0.35);
    std::vector<mortar::OverlapPoint> pts;
    const double measure = overlap(s, m, 6, pts);
    ASSERT_GT(measure, 0.1 * local_measure(s)) << surface_type_name(t);
    ASSERT_LT(measure, 0.9 * local_measure(s)) << surface_type_name(t);
    expect_biorthogonal(t, pts, measure);
    // The full-cell coefficients are not biorthogonal on this part.
    std::vector<mortar::OverlapPoint> full;
    overlap(s, reversed(s), 6, full);
    const int nn = surface_n_nodes(t);
    std::vector<double> a_full(nn * nn), a_part(nn * nn);
    ASSERT_TRUE(mortar::dual_coefficients(t, full, a_full.data()));
    ASSERT_TRUE(mortar::dual_coefficients(t, pts, a_part.data()));
    double diff = 0.0;
    for (int k = 0; k < nn * nn; ++k) diff = std::max(diff, std::abs(a_full[k] - a_part[k]));
    EXPECT_GT(diff, 0.1) << surface_type_name(t);
  }
}

TEST(MortarDualBasis, RefusesTooSmallCoverage) {
  // Partial coverages where the integral of a (transformed) shape function over the covered
  // part is negative: SEG3 covered on its last 1.6 of 2.7 (far end N_0: about -0.0995), QUAD8
  // covered on 49 % towards its third corner (first corner N~_0: about -0.0337).
  struct Case { CellType type; double dx, dy, de0; };
  for (const Case& c : {Case{CellType::Seg3, 1.1, 0.0, -0.0995}, Case{CellType::Quad8, 0.9, 0.35, -0.0337}}) {
    const Cell s = stretched_cell(c.type);
    std::vector<mortar::OverlapPoint> pts;
    overlap(s, shifted_master(s, c.dx, c.dy), 6, pts);
    double de0 = 0.0;
    for (const auto& p : pts) {
      double n[8];
      mortar::slave_shape(c.type, p.xi_s, n);
      de0 += p.w * n[0];
    }
    EXPECT_NEAR(de0, c.de0, 1e-4) << surface_type_name(c.type);
    const int nn = surface_n_nodes(c.type);
    std::vector<double> a(nn * nn, 42.0);
    EXPECT_FALSE(mortar::dual_coefficients(c.type, pts, a.data())) << surface_type_name(c.type);
    for (double v : a) EXPECT_EQ(v, 42.0);
  }
  for (CellType t : kSurfaces) {
    const int nn = surface_n_nodes(t);
    std::vector<double> a(nn * nn, 42.0);
    EXPECT_FALSE(mortar::dual_coefficients(t, {}, a.data()));
    // One point cannot carry n independent functions.
    const Cell s = stretched_cell(t);
    std::vector<mortar::OverlapPoint> pts;
    overlap(s, reversed(s), 1, pts);
    std::vector<mortar::OverlapPoint> one(pts.begin(), pts.begin() + 1);
    EXPECT_FALSE(mortar::dual_coefficients(t, one, a.data())) << surface_type_name(t);
    for (double v : a) EXPECT_EQ(v, 42.0);
  }
}

// AXIS: a SEG3 slave cell from the axis (r = 0 at its first vertex) weighted by r dl. The
// integral of r N over the cell vanishes for the axis vertex, so that vertex carries no
// multiplier (Phi = 0) while the other two dual functions stay biorthogonal to all three
// shape functions and the dual functions still sum to one: the cell keeps its mid-side and
// outer multipliers (before, the whole cell was dropped and its neighbour took its load).
TEST(MortarDualBasis, AxisSeg3FromTheAxisKeepsItsOtherMultipliers) {
  const double h = 0.0125;
  std::vector<mortar::OverlapPoint> pts;
  for (const auto& q : contact::contact_integration_rule(CellType::Seg3, IntegrationScheme::Gauss, 4)) {
    mortar::OverlapPoint p;
    p.xi_s[0] = q.xi[0];
    const double r = h * (1.0 + q.xi[0]) / 2.0;  // node 0 at r = 0, node 1 at r = h, node 2 (mid) at h/2
    p.w = q.weight * (h / 2.0) * r;
    pts.push_back(p);
  }
  const std::vector<double> de = expect_biorthogonal(CellType::Seg3, pts, h * h / 2.0);
  EXPECT_NEAR(de[0], 0.0, 1e-16);
  EXPECT_NEAR(de[1], h * h / 6.0, 1e-16);  // the integral of r N over [0, h] for the outer vertex
  EXPECT_NEAR(de[2], h * h / 3.0, 1e-16);  // and for the mid-side node
  std::vector<double> a(9, 0.0);
  ASSERT_TRUE(mortar::dual_coefficients(CellType::Seg3, pts, a.data()));
  for (int j = 0; j < 3; ++j) EXPECT_EQ(a[j], 0.0) << "Phi of the axis vertex, coefficient " << j;
}

namespace {

// D and M of one SEG2 slave cell [0, 1] on two SEG2 master cells [-0.5, 0.5] and [0.5, 1.5]
// (the master surface facing it, its node order reversed), integrated by hand:
//   dual basis Phi_1 = 2 N_1 - N_2 = 2 - 3x, Phi_2 = 3x - 1 (A = De Me^-1 = [2 -1; -1 2]);
//   D = diag(int N_j) = (1/2, 1/2);
//   M_jl = int Phi_j N_l over the overlaps, master nodes x = -0.5, 0.5, 1.5:
//     slave node x = 0: 3/16, 3/8, -1/16;  slave node x = 1: -1/16, 3/8, 3/16
//   (each row sums to D_jj: the master shape functions sum to one).
TEST(MortarIntegration, DAndMOfAShiftedSeg2PairAreTheHandValues) {
  const double slave[6] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0};
  const double master_cells[2][6] = {{0.5, 0.0, 0.0, -0.5, 0.0, 0.0}, {1.5, 0.0, 0.0, 0.5, 0.0, 0.0}};
  const double master_node_x[2][2] = {{0.5, -0.5}, {1.5, 0.5}};
  std::vector<mortar::OverlapPoint> points;
  std::vector<int> cell_of_point;
  for (int c = 0; c < 2; ++c) {
    const size_t before = points.size();
    EXPECT_NEAR(mortar::overlap_points(CellType::Seg2, slave, CellType::Seg2, master_cells[c], 4, points), 0.5, 1e-15);
    cell_of_point.insert(cell_of_point.end(), points.size() - before, c);
  }
  double a[4];
  ASSERT_TRUE(mortar::dual_coefficients(CellType::Seg2, points, a));
  const double a_hand[4] = {2.0, -1.0, -1.0, 2.0};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(a[k], a_hand[k], 1e-14) << "A entry " << k;
  double d[2] = {0.0, 0.0};
  std::array<std::array<double, 3>, 2> m{};  // slave node x master node (x = -0.5, 0.5, 1.5)
  const auto master_index = [](double x) { return static_cast<int>(std::lround(x + 0.5)); };
  for (size_t p = 0; p < points.size(); ++p) {
    double ns[2], nm[2];
    mortar::slave_shape(CellType::Seg2, points[p].xi_s, ns);
    mortar::slave_shape(CellType::Seg2, points[p].xi_m, nm);
    for (int j = 0; j < 2; ++j) {
      d[j] += points[p].w * ns[j];
      const double phi = a[2 * j] * ns[0] + a[2 * j + 1] * ns[1];
      for (int l = 0; l < 2; ++l) m[j][master_index(master_node_x[cell_of_point[p]][l])] += points[p].w * phi * nm[l];
    }
  }
  EXPECT_NEAR(d[0], 0.5, 1e-15);
  EXPECT_NEAR(d[1], 0.5, 1e-15);
  const double m_hand[2][3] = {{3.0 / 16, 3.0 / 8, -1.0 / 16}, {-1.0 / 16, 3.0 / 8, 3.0 / 16}};
  for (int j = 0; j < 2; ++j)
    for (int l = 0; l < 3; ++l) EXPECT_NEAR(m[j][l], m_hand[j][l], 1e-15) << "M(" << j << ", " << l << ")";
}

}  // namespace
