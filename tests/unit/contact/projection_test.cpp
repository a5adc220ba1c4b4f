// Surface shape functions, orthogonal projection and the master-surface index.
#include <cmath>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "engine/contact/master_search.hpp"
#include "engine/contact/surface_element.hpp"

using namespace lunaster::engine;
using namespace lunaster::engine::contact;

namespace {

const CellType kEveryCellType[] = {CellType::Seg2, CellType::Seg3, CellType::Tria3, CellType::Tria6, CellType::Quad4,
                         CellType::Quad8};

// Node coordinates of a curved cell: reference node positions mapped by a smooth map.
std::vector<double> curved_cell(CellType t, double bend) {
  std::vector<double> xyz;
  for (int a = 0; a < surface_n_nodes(t); ++a) {
    double xi[2];
    surface_reference_node(t, a, xi);
    const double x = 0.7 * xi[0] + 0.1 * xi[1], y = 0.5 * xi[1] - 0.05 * xi[0];
    if (surface_ref_dim(t) == 1) xyz.insert(xyz.end(), {x, bend * x * x, 0.0});
    else xyz.insert(xyz.end(), {x, y, bend * (x * x + 0.5 * y * y)});
  }
  return xyz;
}

}  // namespace

TEST(ContactSurface, ShapeFunctionsInterpolateAndDerivativesMatchFiniteDifferences) {
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> dist(-0.3, 0.3);
  for (CellType t : kEveryCellType) {
    const int nn = surface_n_nodes(t);
    for (int b = 0; b < nn; ++b) {  // Kronecker property
      double xi[2], n[8];
      surface_reference_node(t, b, xi);
      surface_shape(t, xi, n, nullptr, nullptr);
      for (int a = 0; a < nn; ++a) EXPECT_NEAR(n[a], a == b ? 1.0 : 0.0, 1e-14);
    }
    double xi[2] = {0.25 + dist(gen), surface_ref_dim(t) == 1 ? 0.0 : 0.2 + dist(gen) * 0.5};
    double n[8], dn[16], d2n[24], sum = 0;
    surface_shape(t, xi, n, dn, d2n);
    for (int a = 0; a < nn; ++a) sum += n[a];
    EXPECT_NEAR(sum, 1.0, 1e-14);
    const double h = 1e-6;
    for (int k = 0; k < surface_ref_dim(t); ++k) {
      double xp[2] = {xi[0], xi[1]}, xm[2] = {xi[0], xi[1]};
      xp[k] += h, xm[k] -= h;
      double np[8], nm[8], dnp[16], dnm[16];
      surface_shape(t, xp, np, dnp, nullptr);
      surface_shape(t, xm, nm, dnm, nullptr);
      for (int a = 0; a < nn; ++a) {
        EXPECT_NEAR(dn[2 * a + k], (np[a] - nm[a]) / (2 * h), 1e-8);
        for (int l = 0; l < surface_ref_dim(t); ++l) {
          const int m = k == 0 ? (l == 0 ? 0 : 1) : (l == 0 ? 1 : 2);
          EXPECT_NEAR(d2n[3 * a + m], (dnp[2 * a + l] - dnm[2 * a + l]) / (2 * h), 1e-7);
        }
      }
    }
  }
}

TEST(ContactSurface, NormalFollowsNodeOrder) {
  // 2D: tangent (-1,0) (top edge of a body traversed counter-clockwise) -> normal (0,1).
  const double seg[] = {1, 0, 0, -1, 0, 0};
  const double mid[2] = {0, 0};
  const SurfacePoint p = surface_point(CellType::Seg2, seg, mid);
  EXPECT_NEAR(p.n[0], 0.0, 1e-15);
  EXPECT_NEAR(p.n[1], 1.0, 1e-15);
  EXPECT_NEAR(p.jacobian, 1.0, 1e-15);
  // 3D: counter-clockwise square seen from +z -> normal +z, jacobian = area/4.
  const double quad[] = {0, 0, 1, 2, 0, 1, 2, 2, 1, 0, 2, 1};
  const SurfacePoint q = surface_point(CellType::Quad4, quad, mid);
  EXPECT_NEAR(q.n[2], 1.0, 1e-15);
  EXPECT_NEAR(q.jacobian, 1.0, 1e-15);
}

TEST(ContactProjection, RecoversFootOfNormalOnCurvedCells) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> dist(-0.8, 0.8), gap(-0.2, 0.2);
  for (CellType t : kEveryCellType) {
    const std::vector<double> xyz = curved_cell(t, 0.3);
    for (int trial = 0; trial < 20; ++trial) {
      double xi0[2] = {dist(gen), surface_ref_dim(t) == 1 ? 0.0 : dist(gen)};
      if (is_triangle(t)) xi0[0] = 0.5 * (xi0[0] + 0.8) / 1.6 * 0.9, xi0[1] = 0.4 * (xi0[1] + 0.8) / 1.6 + 0.02;
      const SurfacePoint s = surface_point(t, xyz.data(), xi0);
      const double d = gap(gen);
      const double point[3] = {s.x[0] + d * s.n[0], s.x[1] + d * s.n[1], s.x[2] + d * s.n[2]};
      const CellProjection cp = project_on_cell(t, xyz.data(), point);
      ASSERT_TRUE(cp.converged) << surface_type_name(t);
      EXPECT_NEAR(cp.xi[0], xi0[0], 1e-9) << surface_type_name(t);
      EXPECT_NEAR(cp.xi[1], xi0[1], 1e-9) << surface_type_name(t);
      EXPECT_EQ(cp.outside, 0.0);
    }
  }
}

TEST(ContactProjection, StraightSegmentOutsideIsClampedOrRejected) {
  Mesh mesh;
  mesh.dim = 2;
  // Lower body QUAD4 [0,1]x[-1,0] and its top edge oriented outward (+y): nodes 2 -> 3.
  mesh.add_node(0, -1, 0), mesh.add_node(1, -1, 0), mesh.add_node(1, 0, 0), mesh.add_node(0, 0, 0);
  mesh.add_cell(CellType::Quad4, {0, 1, 2, 3});
  const int edge = mesh.add_cell(CellType::Seg2, {2, 3});
  MasterSurface master(mesh, {edge}, false);
  EXPECT_EQ(master.n_flipped(), 0);
  master.update(mesh.coords);
  const double inside[3] = {0.25, 0.1, 0};
  MasterProjection p = master.project(inside, 0.5);
  ASSERT_TRUE(p.found);
  EXPECT_NEAR(p.x[0], 0.25, 1e-14);
  EXPECT_NEAR(p.normal[1], 1.0, 1e-14);
  const double beyond[3] = {1.2, -0.05, 0};  // 0.4 reference units beyond the end: clamped
  p = master.project(beyond, 0.5);
  ASSERT_TRUE(p.found);
  EXPECT_NEAR(p.x[0], 1.0, 1e-14);
  EXPECT_NEAR(p.outside, 0.4, 1e-12);
  const double far[3] = {1.6, 0.0, 0};  // 1.2 beyond: rejected
  EXPECT_FALSE(master.project(far, 0.5).found);
  // An edge listed against its body's orientation is flipped.
  const int reversed = mesh.add_cell(CellType::Seg2, {3, 2});
  MasterSurface flipped(mesh, {reversed}, false);
  EXPECT_EQ(flipped.n_flipped(), 1);
  flipped.update(mesh.coords);
  EXPECT_NEAR(flipped.project(inside, 0.5).normal[1], 1.0, 1e-14);
}

TEST(ContactProjection, GridSearchMatchesBruteForce) {
  // Wavy master line of 200 SEG3 cells; points above/below it.
  Mesh mesh;
  mesh.dim = 2;
  const int n = 200;
  for (int i = 0; i <= 2 * n; ++i) {
    const double x = double(i) / (2 * n) * 10.0;
    mesh.add_node(x, 0.2 * std::sin(x), 0);
  }
  std::vector<int> cells;
  for (int i = 0; i < n; ++i) cells.push_back(mesh.add_cell(CellType::Seg3, {2 * i, 2 * i + 2, 2 * i + 1}));
  MasterSurface master(mesh, cells, false);
  master.update(mesh.coords);
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> xs(0.1, 9.9), ys(-0.4, 0.4);
  for (int trial = 0; trial < 100; ++trial) {
    const double point[3] = {xs(gen), ys(gen), 0.0};
    const MasterProjection p = master.project(point, 0.5);
    ASSERT_TRUE(p.found);
    double best = 1e300;
    for (int c : cells) {
      double xyz[9];
      for (int a = 0; a < 3; ++a)
        for (int i = 0; i < 3; ++i) xyz[3 * a + i] = mesh.node(mesh.cell(c)[a])[i];
      CellProjection cp = project_on_cell(CellType::Seg3, xyz, point);
      if (!cp.converged || cp.outside > 0.5) continue;
      clamp_to_cell(CellType::Seg3, cp.xi);
      const SurfacePoint s = surface_point(CellType::Seg3, xyz, cp.xi);
      best = std::min(best, std::hypot(s.x[0] - point[0], s.x[1] - point[1]));
    }
    EXPECT_NEAR(p.distance, best, 1e-10);
  }
}

namespace {

// Wavy 3D master surface z = 0.05 sin(3x) cos(2y) on [0,2]^2: n x n QUAD8 cells, or
// each square split into two TRIA6 along its (i,j)-(i+1,j+1) diagonal.
std::vector<int> wavy_surface(Mesh& mesh, int n, bool triangles) {
  mesh.dim = 3;
  const int m = 2 * n;
  std::vector<int> grid((m + 1) * (m + 1));
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      const double x = 2.0 * i / m, y = 2.0 * j / m;
      grid[j * (m + 1) + i] = mesh.add_node(x, y, 0.05 * std::sin(3 * x) * std::cos(2 * y));
    }
  auto at = [&](int i, int j) { return grid[j * (m + 1) + i]; };
  std::vector<int> cells;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int I = 2 * i, J = 2 * j;
      if (triangles) {
        cells.push_back(mesh.add_cell(CellType::Tria6, {at(I, J), at(I + 2, J), at(I + 2, J + 2), at(I + 1, J),
                                                        at(I + 2, J + 1), at(I + 1, J + 1)}));
        cells.push_back(mesh.add_cell(CellType::Tria6, {at(I, J), at(I + 2, J + 2), at(I, J + 2), at(I + 1, J + 1),
                                                        at(I + 1, J + 2), at(I, J + 1)}));
      } else {
        cells.push_back(mesh.add_cell(CellType::Quad8, {at(I, J), at(I + 2, J), at(I + 2, J + 2), at(I, J + 2),
                                                        at(I + 1, J), at(I + 2, J + 1), at(I + 1, J + 2),
                                                        at(I, J + 1)}));
      }
    }
  return cells;
}

/// The wavy surface as a master surface, its grid built on the mesh's coordinates.
struct WavyMaster {
  Mesh mesh;
  std::vector<int> cells;
  std::unique_ptr<MasterSurface> master;
  WavyMaster(int n, bool triangles) : cells(wavy_surface(mesh, n, triangles)) {
    master = std::make_unique<MasterSurface>(mesh, cells, false);
    master->update(mesh.coords);
  }
};

}  // namespace

TEST(ContactProjection, GridSearchMatchesBruteForceOn3dQuadraticSurfaces) {
  // The box pruning of MasterSurface::project must never skip the closest cell,
  // including on curved cells that bulge out of their nodes' bounding box.
  for (bool triangles : {false, true}) {
    const WavyMaster wavy(12, triangles);
    const Mesh& mesh = wavy.mesh;
    const std::vector<int>& cells = wavy.cells;
    const MasterSurface& master = *wavy.master;
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> xy(0.05, 1.95), z(-0.15, 0.15);
    for (int trial = 0; trial < 300; ++trial) {
      const double point[3] = {xy(gen), xy(gen), z(gen)};
      const MasterProjection p = master.project(point, 0.5);
      ASSERT_TRUE(p.found);
      double best = 1e300;
      for (int c : cells) {
        const CellType t = mesh.cell_types[c];
        double xyz[3 * kMaxSurfaceNodes];
        for (int a = 0; a < surface_n_nodes(t); ++a)
          for (int i = 0; i < 3; ++i) xyz[3 * a + i] = mesh.node(mesh.cell(c)[a])[i];
        CellProjection cp = project_on_cell(t, xyz, point);
        if (!cp.converged || cp.outside > 0.5) continue;
        clamp_to_cell(t, cp.xi);
        const SurfacePoint s = surface_point(t, xyz, cp.xi);
        best = std::min(best, std::sqrt((s.x[0] - point[0]) * (s.x[0] - point[0]) +
                                        (s.x[1] - point[1]) * (s.x[1] - point[1]) +
                                        (s.x[2] - point[2]) * (s.x[2] - point[2])));
      }
      EXPECT_NEAR(p.distance, best, 1e-10) << (triangles ? "TRIA6" : "QUAD8") << " trial " << trial;
    }
  }
}

TEST(ContactProjection, TwoThreadsProjectingAtOnceGetTheSerialResults) {
  // Contact pairing shares its points between two threads that project on one surface at
  // once (ContactProblem::pair): project() must read the surface only.
  const WavyMaster wavy(16, false);
  const MasterSurface& master = *wavy.master;
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> xy(0.0, 2.0), z(-0.15, 0.15);
  const int n = 20000;
  std::vector<double> points(3 * n);
  for (int k = 0; k < n; ++k) points[3 * k] = xy(gen), points[3 * k + 1] = xy(gen), points[3 * k + 2] = z(gen);
  std::vector<MasterProjection> serial(n), shared(n);
  for (int k = 0; k < n; ++k) serial[k] = master.project(&points[3 * k], 0.5);
  auto range = [&](int begin, int end) {
    for (int k = begin; k < end; ++k) shared[k] = master.project(&points[3 * k], 0.5);
  };
  std::thread helper(range, n / 2, n);
  range(0, n / 2);
  helper.join();
  for (int k = 0; k < n; ++k) {
    ASSERT_EQ(shared[k].found, serial[k].found) << k;
    ASSERT_EQ(shared[k].cell, serial[k].cell) << k;
    ASSERT_EQ(shared[k].xi[0], serial[k].xi[0]) << k;
    ASSERT_EQ(shared[k].xi[1], serial[k].xi[1]) << k;
  }
}

TEST(ContactProjection, TiesAtSharedNodesAreDecidedByCellIndexNotRoundOff) {
  // A point on a node shared by six curved triangles (kinks between them), moved by
  // round-off-sized offsets, must always pair with the same cell: the lowest index
  // among the cells containing its foot. Otherwise a pairing flips between
  // neighbouring cells of a kinked master from one geometry iteration to the next.
  Mesh mesh;
  const std::vector<int> cells = wavy_surface(mesh, 4, true);
  MasterSurface master(mesh, cells, false);
  master.update(mesh.coords);
  const double* node = mesh.node(mesh.cell(cells[10])[0]);  // an interior vertex (x, y) = (1, 0.5)
  int expected = -1;
  for (int c : cells)
    for (int a = 0; a < 6 && expected < 0; ++a)
      if (mesh.cell(c)[a] == mesh.cell(cells[10])[0]) expected = c;
  // 1e-11: round-off of the size a solve leaves in displaced coordinates (one penalty deck
  // solved two ways paired a slave node over a master node with either neighbour).
  for (const double eps : {1e-13, 1e-11}) {
    for (int s = 0; s < 27; ++s) {
      const double point[3] = {node[0] + eps * (s % 3 - 1), node[1] + eps * (s / 3 % 3 - 1),
                               node[2] + eps * (s / 9 - 1)};
      const MasterProjection p = master.project(point, 0.5);
      ASSERT_TRUE(p.found);
      EXPECT_EQ(p.cell, expected) << "offset " << eps << " direction " << s;
    }
  }
}

TEST(ContactProjection, DomedQuadraticCellIsFoundAboveItsNodes) {
  // A quadratic cell whose mid-side nodes all rise by h bulges above every one of its nodes
  // (to 2h for QUAD8, 4h/3 for TRIA6). A flat cell nearer than the domed cell's node box but
  // farther than the dome itself must not win: the box pruning has to cover the bulge.
  for (const CellType t : {CellType::Quad8, CellType::Tria6}) {
    const double h = 0.3, apex = t == CellType::Quad8 ? 2 * h : 4 * h / 3;
    Mesh mesh;
    mesh.dim = 3;
    std::vector<int> dome_nodes;
    for (int a = 0; a < surface_n_nodes(t); ++a) {
      double xi[2];
      surface_reference_node(t, a, xi);
      const double x = t == CellType::Quad8 ? 0.5 * (xi[0] + 1) : xi[0], y = t == CellType::Quad8 ? 0.5 * (xi[1] + 1) : xi[1];
      dome_nodes.push_back(mesh.add_node(x, y, a < surface_n_vertices(t) ? 0.0 : h));
    }
    const int dome = mesh.add_cell(t, dome_nodes);
    // The point, 0.02 above the apex (at the reference centre), and a flat lid 0.08 above it.
    const double centre[2] = {t == CellType::Quad8 ? 0.0 : 1.0 / 3, t == CellType::Quad8 ? 0.0 : 1.0 / 3};
    double xyz[3 * kMaxSurfaceNodes];
    for (int a = 0; a < surface_n_nodes(t); ++a)
      for (int i = 0; i < 3; ++i) xyz[3 * a + i] = mesh.node(dome_nodes[a])[i];
    const SurfacePoint top = surface_point(t, xyz, centre);
    ASSERT_NEAR(top.x[2], apex, 1e-14);
    const double point[3] = {top.x[0], top.x[1], apex + 0.02}, lid_z = apex + 0.1;
    const int lid = mesh.add_cell(CellType::Quad4, {mesh.add_node(-0.5, -0.5, lid_z), mesh.add_node(1.5, -0.5, lid_z),
                                                    mesh.add_node(1.5, 1.5, lid_z), mesh.add_node(-0.5, 1.5, lid_z)});
    MasterSurface master(mesh, {dome, lid}, false);
    master.update(mesh.coords);
    const MasterProjection p = master.project(point, 0.5);
    ASSERT_TRUE(p.found);
    EXPECT_EQ(p.cell, dome) << surface_type_name(t);
    EXPECT_NEAR(p.distance, 0.02, 1e-12) << surface_type_name(t);
  }
}
