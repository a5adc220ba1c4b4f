#include "engine/contact/surface_element.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"

namespace lunaster::engine::contact {

namespace {

// Corner signs of QUAD4/QUAD8 and mid-edge positions of QUAD8 (MED order).
constexpr double kQuadCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
constexpr double kQuadMid[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
// TRIA6 mid-edge node a = 3 + e joins vertices kTriEdge[e][0..1].
constexpr int kTriEdge[3][2] = {{0, 1}, {1, 2}, {2, 0}};

void set(double* p, int i, double v) {
  if (p) p[i] = v;
}

void shape_seg(CellType type, double s, double* n) {
  if (type == CellType::Seg2) {
    n[0] = 0.5 * (1 - s), n[1] = 0.5 * (1 + s);
    return;
  }
  n[0] = 0.5 * s * (s - 1), n[1] = 0.5 * s * (s + 1), n[2] = 1 - s * s;
}

void shape_tria(CellType type, const double* xi, double* n, double* dn, double* d2n) {
  const double l[3] = {1 - xi[0] - xi[1], xi[0], xi[1]};
  const double dl[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  if (type == CellType::Tria3) {
    for (int a = 0; a < 3; ++a) {
      set(n, a, l[a]);
      set(dn, 2 * a, dl[a][0]), set(dn, 2 * a + 1, dl[a][1]);
      for (int m = 0; m < 3; ++m) set(d2n, 3 * a + m, 0.0);
    }
    return;
  }
  for (int a = 0; a < 3; ++a) {  // N = L (2L - 1)
    set(n, a, l[a] * (2 * l[a] - 1));
    for (int k = 0; k < 2; ++k) set(dn, 2 * a + k, (4 * l[a] - 1) * dl[a][k]);
    set(d2n, 3 * a, 4 * dl[a][0] * dl[a][0]);
    set(d2n, 3 * a + 1, 4 * dl[a][0] * dl[a][1]);
    set(d2n, 3 * a + 2, 4 * dl[a][1] * dl[a][1]);
  }
  for (int e = 0; e < 3; ++e) {  // N = 4 La Lb
    const int a = kTriEdge[e][0], b = kTriEdge[e][1], node = 3 + e;
    set(n, node, 4 * l[a] * l[b]);
    for (int k = 0; k < 2; ++k) set(dn, 2 * node + k, 4 * (l[b] * dl[a][k] + l[a] * dl[b][k]));
    set(d2n, 3 * node, 8 * dl[a][0] * dl[b][0]);
    set(d2n, 3 * node + 1, 4 * (dl[a][0] * dl[b][1] + dl[a][1] * dl[b][0]));
    set(d2n, 3 * node + 2, 8 * dl[a][1] * dl[b][1]);
  }
}

void shape_quad4(const double* xi, double* n, double* dn, double* d2n) {
  for (int a = 0; a < 4; ++a) {
    const double si = kQuadCorner[a][0], ti = kQuadCorner[a][1];
    set(n, a, 0.25 * (1 + si * xi[0]) * (1 + ti * xi[1]));
    set(dn, 2 * a, 0.25 * si * (1 + ti * xi[1]));
    set(dn, 2 * a + 1, 0.25 * ti * (1 + si * xi[0]));
    set(d2n, 3 * a, 0.0), set(d2n, 3 * a + 1, 0.25 * si * ti), set(d2n, 3 * a + 2, 0.0);
  }
}

void shape_quad8(const double* xi, double* n, double* dn, double* d2n) {
  const double s = xi[0], t = xi[1];
  for (int a = 0; a < 4; ++a) {  // corners: (1+si s)(1+ti t)(si s + ti t - 1)/4
    const double si = kQuadCorner[a][0], ti = kQuadCorner[a][1];
    const double p = 1 + si * s, q = 1 + ti * t;
    set(n, a, 0.25 * p * q * (si * s + ti * t - 1));
    set(dn, 2 * a, 0.25 * si * q * (2 * si * s + ti * t));
    set(dn, 2 * a + 1, 0.25 * ti * p * (si * s + 2 * ti * t));
    set(d2n, 3 * a, 0.5 * q), set(d2n, 3 * a + 1, 0.25 * si * ti * (2 * si * s + 2 * ti * t + 1));
    set(d2n, 3 * a + 2, 0.5 * p);
  }
  for (int e = 0; e < 4; ++e) {
    const int a = 4 + e;
    const double si = kQuadMid[e][0], ti = kQuadMid[e][1];
    if (si == 0.0) {  // (1 - s^2)(1 + ti t)/2
      set(n, a, 0.5 * (1 - s * s) * (1 + ti * t));
      set(dn, 2 * a, -s * (1 + ti * t)), set(dn, 2 * a + 1, 0.5 * ti * (1 - s * s));
      set(d2n, 3 * a, -(1 + ti * t)), set(d2n, 3 * a + 1, -s * ti), set(d2n, 3 * a + 2, 0.0);
    } else {  // (1 + si s)(1 - t^2)/2
      set(n, a, 0.5 * (1 + si * s) * (1 - t * t));
      set(dn, 2 * a, 0.5 * si * (1 - t * t)), set(dn, 2 * a + 1, -t * (1 + si * s));
      set(d2n, 3 * a, 0.0), set(d2n, 3 * a + 1, -t * si), set(d2n, 3 * a + 2, -(1 + si * s));
    }
  }
}

}  // namespace

bool is_surface_type(CellType type) {
  switch (type) {
    case CellType::Seg2: case CellType::Seg3: case CellType::Tria3: case CellType::Tria6:
    case CellType::Quad4: case CellType::Quad8: return true;
    default: return false;
  }
}

int surface_n_nodes(CellType type) {
  switch (type) {
    case CellType::Seg2: return 2;
    case CellType::Seg3: return 3;
    case CellType::Tria3: return 3;
    case CellType::Tria6: return 6;
    case CellType::Quad4: return 4;
    case CellType::Quad8: return 8;
    default: LUNASTER_ASSERT(false, "not a contact surface cell type");
  }
  return 0;
}

int surface_n_vertices(CellType type) { return surface_n_nodes(linear_type(type)); }

int surface_ref_dim(CellType type) {
  return (type == CellType::Seg2 || type == CellType::Seg3) ? 1 : 2;
}

CellType linear_type(CellType type) {
  switch (type) {
    case CellType::Seg3: return CellType::Seg2;
    case CellType::Tria6: return CellType::Tria3;
    case CellType::Quad8: return CellType::Quad4;
    default: return type;
  }
}

int topological_dim(CellType type) {
  switch (type) {
    case CellType::Point1: return 0;
    case CellType::Seg2: case CellType::Seg3: return 1;
    case CellType::Tria3: case CellType::Tria6: case CellType::Quad4: case CellType::Quad8: return 2;
    default: return 3;
  }
}

const char* surface_type_name(CellType type) {
  switch (type) {
    case CellType::Seg2: return "SEG2";
    case CellType::Seg3: return "SEG3";
    case CellType::Tria3: return "TRIA3";
    case CellType::Tria6: return "TRIA6";
    case CellType::Quad4: return "QUAD4";
    case CellType::Quad8: return "QUAD8";
    default: return "(not a surface cell)";
  }
}

bool is_triangle(CellType type) { return type == CellType::Tria3 || type == CellType::Tria6; }

void surface_shape(CellType type, const double* xi, double* n, double* dn, double* d2n) {
  const int nn = surface_n_nodes(type);
  if (dn) std::fill(dn, dn + 2 * nn, 0.0);
  if (d2n) std::fill(d2n, d2n + 3 * nn, 0.0);
  switch (type) {
    case CellType::Seg2: case CellType::Seg3: {
      // Segment derivatives are stored with stride 2 / 3 like the faces.
      double tn[3], tdn[3], td2n[3];
      shape_seg(type, xi[0], tn);
      const double s = xi[0];
      if (type == CellType::Seg2) {
        tdn[0] = -0.5, tdn[1] = 0.5, td2n[0] = td2n[1] = 0.0;
      } else {
        tdn[0] = s - 0.5, tdn[1] = s + 0.5, tdn[2] = -2 * s;
        td2n[0] = 1.0, td2n[1] = 1.0, td2n[2] = -2.0;
      }
      for (int a = 0; a < nn; ++a) {
        set(n, a, tn[a]);
        set(dn, 2 * a, tdn[a]);
        set(d2n, 3 * a, td2n[a]);
      }
      return;
    }
    case CellType::Tria3: case CellType::Tria6: shape_tria(type, xi, n, dn, d2n); return;
    case CellType::Quad4: shape_quad4(xi, n, dn, d2n); return;
    case CellType::Quad8: shape_quad8(xi, n, dn, d2n); return;
    default: LUNASTER_ASSERT(false, "not a contact surface cell type");
  }
}

void surface_reference_node(CellType type, int local_node, double* xi) {
  xi[0] = xi[1] = 0.0;
  switch (type) {
    case CellType::Seg2: case CellType::Seg3: {
      static constexpr double s[3] = {-1, 1, 0};
      xi[0] = s[local_node];
      return;
    }
    case CellType::Tria3: case CellType::Tria6: {
      static constexpr double p[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
      xi[0] = p[local_node][0], xi[1] = p[local_node][1];
      return;
    }
    case CellType::Quad4: case CellType::Quad8: {
      const double* p = local_node < 4 ? kQuadCorner[local_node] : kQuadMid[local_node - 4];
      xi[0] = p[0], xi[1] = p[1];
      return;
    }
    default: LUNASTER_ASSERT(false, "not a contact surface cell type");
  }
}

SurfacePoint surface_point(CellType type, const double* xyz, const double* xi) {
  double n[kMaxSurfaceNodes], dn[2 * kMaxSurfaceNodes];
  surface_shape(type, xi, n, dn, nullptr);
  SurfacePoint p;
  const int nn = surface_n_nodes(type);
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < 3; ++i) {
      p.x[i] += n[a] * xyz[3 * a + i];
      p.t[0][i] += dn[2 * a] * xyz[3 * a + i];
      p.t[1][i] += dn[2 * a + 1] * xyz[3 * a + i];
    }
  double normal[3];
  if (surface_ref_dim(type) == 1) {
    normal[0] = p.t[0][1], normal[1] = -p.t[0][0], normal[2] = 0.0;
  } else {
    const double* a = p.t[0];
    const double* b = p.t[1];
    normal[0] = a[1] * b[2] - a[2] * b[1];
    normal[1] = a[2] * b[0] - a[0] * b[2];
    normal[2] = a[0] * b[1] - a[1] * b[0];
  }
  const double len = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  p.jacobian = len;
  if (len > 0.0 && std::isfinite(len))
    for (int i = 0; i < 3; ++i) p.n[i] = normal[i] / len;
  return p;
}

double outside_distance(CellType type, const double* xi) {
  if (surface_ref_dim(type) == 1) return std::max(0.0, std::abs(xi[0]) - 1.0);
  if (is_triangle(type)) return std::max({0.0, -xi[0], -xi[1], xi[0] + xi[1] - 1.0});
  return std::max({0.0, std::abs(xi[0]) - 1.0, std::abs(xi[1]) - 1.0});
}

void clamp_to_cell(CellType type, double* xi) {
  if (surface_ref_dim(type) == 1) {
    xi[0] = std::clamp(xi[0], -1.0, 1.0);
    xi[1] = 0.0;
    return;
  }
  if (!is_triangle(type)) {
    xi[0] = std::clamp(xi[0], -1.0, 1.0), xi[1] = std::clamp(xi[1], -1.0, 1.0);
    return;
  }
  // Nearest point of the reference triangle (Euclidean in reference coordinates).
  if (xi[0] >= 0 && xi[1] >= 0 && xi[0] + xi[1] <= 1) return;
  double best[2] = {0, 0}, best_d = 1e300;
  const double v[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (int e = 0; e < 3; ++e) {
    const double* a = v[e];
    const double* b = v[(e + 1) % 3];
    const double d[2] = {b[0] - a[0], b[1] - a[1]};
    double s = ((xi[0] - a[0]) * d[0] + (xi[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1]);
    s = std::clamp(s, 0.0, 1.0);
    const double q[2] = {a[0] + s * d[0], a[1] + s * d[1]};
    const double dist = (q[0] - xi[0]) * (q[0] - xi[0]) + (q[1] - xi[1]) * (q[1] - xi[1]);
    if (dist < best_d) best_d = dist, best[0] = q[0], best[1] = q[1];
  }
  xi[0] = best[0], xi[1] = best[1];
}

std::unordered_map<int, std::array<double, 3>> node_normals(const Mesh& mesh, const std::vector<int>& cells) {
  std::unordered_map<int, std::array<double, 3>> sum;
  double xyz[3 * kMaxSurfaceNodes];
  for (int c : cells) {
    const CellType type = mesh.cell_types[c];
    const int nn = surface_n_nodes(type);
    for (int a = 0; a < nn; ++a)
      for (int i = 0; i < 3; ++i) xyz[3 * a + i] = mesh.node(mesh.cell(c)[a])[i];
    for (int b = 0; b < nn; ++b) {
      double xi[2];
      surface_reference_node(type, b, xi);
      const SurfacePoint sp = surface_point(type, xyz, xi);
      if (sp.jacobian == 0.0) continue;
      auto [it, fresh] = sum.try_emplace(mesh.cell(c)[b], std::array<double, 3>{0.0, 0.0, 0.0});
      std::array<double, 3>& total = it->second;
      const double agree = total[0] * sp.n[0] + total[1] * sp.n[1] + total[2] * sp.n[2];
      const double sign = fresh || agree >= 0.0 ? 1.0 : -1.0;
      for (int i = 0; i < 3; ++i) total[i] += sign * sp.n[i];
    }
  }
  for (auto& [node, n] : sum) {
    const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& v : n) v = norm > 1e-12 ? v / norm : 0.0;
  }
  return sum;
}

}  // namespace lunaster::engine::contact
