/// Shape functions on the MED reference cells (see shape.hpp and
/// engine/mesh/cell_topology.hpp for the node coordinates). Every family is
/// written once in closed form (Lagrange on simplices and prisms, tensor-product
/// Q1, serendipity Q2) and driven by the per-type node tables below.
#include "engine/fe/shape.hpp"

#include <array>

#include "engine/core/error.hpp"
#include "engine/fe/reference_element.hpp"

namespace lunaster::engine {
namespace {

// ---- reference node tables (MED order) ----
// 3D cells: the right-hand normal of face (0,1,2) points out of the cell, as in
// MED files (cell_topology.hpp); with these coordinates a correctly oriented
// MED cell has a positive Jacobian.
constexpr double kSeg2[2][3] = {{-1, 0, 0}, {1, 0, 0}};
constexpr double kSeg3[3][3] = {{-1, 0, 0}, {1, 0, 0}, {0, 0, 0}};
constexpr double kTria[6][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}};
constexpr double kQuad[8][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0},
                                {0, -1, 0},  {1, 0, 0},  {0, 1, 0}, {-1, 0, 0}};
constexpr double kTetraV[4][3] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
constexpr double kPentaV[6][3] = {{0, 0, -1}, {0, 1, -1}, {1, 0, -1}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
constexpr double kHexaV[8][3] = {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1},
                                 {-1, -1, 1},  {-1, 1, 1},  {1, 1, 1},  {1, -1, 1}};

// Mid-side node edges (vertex pairs), MED order.
constexpr int kTriaEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kQuadEdges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
constexpr int kTetraEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr int kPentaEdges[9][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
constexpr int kHexaEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// Barycentric coordinates L_i = c_i + g_i . xi of the simplices and the prism triangle.
constexpr double kTriaC[3] = {1, 0, 0};
constexpr double kTriaG[3][3] = {{-1, -1, 0}, {1, 0, 0}, {0, 1, 0}};
constexpr double kTetraC[4] = {1, 0, 0, 0};
constexpr double kTetraG[4][3] = {{-1, -1, -1}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
constexpr double kPentaC[3] = {1, 0, 0};  // prism triangle (xi, eta): vertices (0,0) (0,1) (1,0)
constexpr double kPentaG[3][3] = {{-1, -1, 0}, {0, 1, 0}, {1, 0, 0}};

struct Out {
  double* n;
  double* dn;
  int dim;
  void set(int a, double value, const double* grad) const {
    if (n) n[a] = value;
    if (dn)
      for (int k = 0; k < dim; ++k) dn[a * dim + k] = grad[k];
  }
};

void seg(int order, double x, const Out& o) {
  if (order == 1) {
    const double g0 = -0.5, g1 = 0.5;
    o.set(0, 0.5 * (1 - x), &g0);
    o.set(1, 0.5 * (1 + x), &g1);
    return;
  }
  const double g0 = x - 0.5, g1 = x + 0.5, g2 = -2 * x;
  o.set(0, -0.5 * x * (1 - x), &g0);
  o.set(1, 0.5 * x * (1 + x), &g1);
  o.set(2, 1 - x * x, &g2);
}

/// Lagrange P1/P2 on a simplex with `nv` vertices and barycentrics (c, g).
template <int NV>
void simplex(int order, const double* xi, const double (&c)[NV], const double (&g)[NV][3],
             const int (*edges)[2], int n_edges, const Out& o) {
  double l[NV];
  for (int i = 0; i < NV; ++i) l[i] = c[i] + g[i][0] * xi[0] + g[i][1] * xi[1] + g[i][2] * xi[2];
  double grad[3];
  for (int i = 0; i < NV; ++i) {
    if (order == 1) {
      o.set(i, l[i], g[i]);
    } else {
      for (int k = 0; k < 3; ++k) grad[k] = (4 * l[i] - 1) * g[i][k];
      o.set(i, l[i] * (2 * l[i] - 1), grad);
    }
  }
  if (order == 1) return;
  for (int e = 0; e < n_edges; ++e) {
    const int i = edges[e][0], j = edges[e][1];
    for (int k = 0; k < 3; ++k) grad[k] = 4 * (l[j] * g[i][k] + l[i] * g[j][k]);
    o.set(NV + e, 4 * l[i] * l[j], grad);
  }
}

/// Q1 (order 1) or serendipity Q2 (order 2) on [-1,1]^d.
void tensor(int dim, int order, const double* xi, const double (*vert)[3], const int (*edges)[2], int n_edges,
            const Out& o) {
  const int nv = 1 << dim;
  const double scale = 1.0 / (1 << dim);
  double grad[3];
  for (int a = 0; a < nv; ++a) {
    double f[3], p = 1, s = -(dim - 1);
    for (int k = 0; k < dim; ++k) {
      f[k] = 1 + xi[k] * vert[a][k];
      p *= f[k];
      s += xi[k] * vert[a][k];
    }
    for (int j = 0; j < dim; ++j) {
      double others = 1;
      for (int k = 0; k < dim; ++k)
        if (k != j) others *= f[k];
      grad[j] = order == 1 ? scale * vert[a][j] * others : scale * vert[a][j] * (others * s + p);
    }
    o.set(a, order == 1 ? scale * p : scale * p * s, grad);
  }
  if (order == 1) return;
  for (int e = 0; e < n_edges; ++e) {
    const double* va = vert[edges[e][0]];
    const double* vb = vert[edges[e][1]];
    double mid[3];
    int m = 0;
    for (int k = 0; k < dim; ++k) {
      mid[k] = 0.5 * (va[k] + vb[k]);
      if (va[k] != vb[k]) m = k;
    }
    const double bubble = 1 - xi[m] * xi[m];
    double q = 1;
    for (int k = 0; k < dim; ++k)
      if (k != m) q *= 1 + xi[k] * mid[k];
    for (int j = 0; j < dim; ++j) {
      if (j == m) {
        grad[j] = 2 * scale * (-2 * xi[m]) * q;
        continue;
      }
      double others = 1;
      for (int k = 0; k < dim; ++k)
        if (k != m && k != j) others *= 1 + xi[k] * mid[k];
      grad[j] = 2 * scale * bubble * mid[j] * others;
    }
    o.set(nv + e, 2 * scale * bubble * q, grad);
  }
}

/// PENTA6/PENTA15: triangle (xi, eta) x segment zeta.
void prism(int order, const double* xi, const Out& o) {
  double l[3];
  for (int i = 0; i < 3; ++i) l[i] = kPentaC[i] + kPentaG[i][0] * xi[0] + kPentaG[i][1] * xi[1];
  const double z = xi[2];
  double grad[3];
  for (int a = 0; a < 6; ++a) {
    const int t = a % 3;
    const double s = a < 3 ? -1.0 : 1.0, h = 1 + s * z;
    const double* g = kPentaG[t];
    if (order == 1) {
      grad[0] = 0.5 * h * g[0];
      grad[1] = 0.5 * h * g[1];
      grad[2] = 0.5 * s * l[t];
      o.set(a, 0.5 * h * l[t], grad);
    } else {  // 0.5 L (1+s z)(2L - 2 + s z)
      grad[0] = 0.5 * h * (4 * l[t] - 2 + s * z) * g[0];
      grad[1] = 0.5 * h * (4 * l[t] - 2 + s * z) * g[1];
      grad[2] = 0.5 * l[t] * s * (2 * l[t] - 1 + 2 * s * z);
      o.set(a, 0.5 * l[t] * h * (2 * l[t] - 2 + s * z), grad);
    }
  }
  if (order == 1) return;
  for (int e = 0; e < 9; ++e) {
    const int i = kPentaEdges[e][0] % 3, j = kPentaEdges[e][1] % 3;
    if (e < 6) {  // triangle edges on the bottom (e<3) or top face
      const double s = e < 3 ? -1.0 : 1.0, h = 1 + s * z;
      for (int k = 0; k < 2; ++k) grad[k] = 2 * h * (l[j] * kPentaG[i][k] + l[i] * kPentaG[j][k]);
      grad[2] = 2 * l[i] * l[j] * s;
      o.set(6 + e, 2 * l[i] * l[j] * h, grad);
    } else {  // vertical edges
      for (int k = 0; k < 2; ++k) grad[k] = (1 - z * z) * kPentaG[i][k];
      grad[2] = -2 * z * l[i];
      o.set(6 + e, l[i] * (1 - z * z), grad);
    }
  }
}

}  // namespace

void shape_functions(CellType type, const double* xi, double* n, double* dn) {
  const Out o{n, dn, cell_dim(type)};
  switch (type) {
    case CellType::Seg2: return seg(1, xi[0], o);
    case CellType::Seg3: return seg(2, xi[0], o);
    case CellType::Tria3: return simplex<3>(1, xi, kTriaC, kTriaG, kTriaEdges, 3, o);
    case CellType::Tria6: return simplex<3>(2, xi, kTriaC, kTriaG, kTriaEdges, 3, o);
    case CellType::Tetra4: return simplex<4>(1, xi, kTetraC, kTetraG, kTetraEdges, 6, o);
    case CellType::Tetra10: return simplex<4>(2, xi, kTetraC, kTetraG, kTetraEdges, 6, o);
    case CellType::Quad4: return tensor(2, 1, xi, kQuad, kQuadEdges, 4, o);
    case CellType::Quad8: return tensor(2, 2, xi, kQuad, kQuadEdges, 4, o);
    case CellType::Hexa8: return tensor(3, 1, xi, kHexaV, kHexaEdges, 12, o);
    case CellType::Hexa20: return tensor(3, 2, xi, kHexaV, kHexaEdges, 12, o);
    case CellType::Penta6: return prism(1, xi, o);
    case CellType::Penta15: return prism(2, xi, o);
    default: break;
  }
  throw InternalError("shape_functions: unsupported cell type");
}

void reference_node(CellType type, int local_node, double* xi) {
  LUNASTER_ASSERT(local_node >= 0 && local_node < cell_n_nodes(type), "reference_node: bad local node");
  const double* p = nullptr;
  const double(*vert)[3] = nullptr;
  const int(*edges)[2] = nullptr;
  int nv = 0;
  switch (type) {
    case CellType::Seg2: p = kSeg2[local_node]; break;
    case CellType::Seg3: p = kSeg3[local_node]; break;
    case CellType::Tria3: case CellType::Tria6: p = kTria[local_node]; break;
    case CellType::Quad4: case CellType::Quad8: p = kQuad[local_node]; break;
    case CellType::Tetra4: case CellType::Tetra10: vert = kTetraV, edges = kTetraEdges, nv = 4; break;
    case CellType::Penta6: case CellType::Penta15: vert = kPentaV, edges = kPentaEdges, nv = 6; break;
    case CellType::Hexa8: case CellType::Hexa20: vert = kHexaV, edges = kHexaEdges, nv = 8; break;
    default: throw InternalError("reference_node: unsupported cell type");
  }
  const int dim = cell_dim(type);
  for (int k = 0; k < dim; ++k) {
    if (p) {
      xi[k] = p[k];
    } else if (local_node < nv) {
      xi[k] = vert[local_node][k];
    } else {
      const int* e = edges[local_node - nv];
      xi[k] = 0.5 * (vert[e[0]][k] + vert[e[1]][k]);
    }
  }
}

}  // namespace lunaster::engine
