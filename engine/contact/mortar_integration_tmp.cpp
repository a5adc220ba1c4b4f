// TEMPORARY 2D-only stand-in (not committed): replaced by the real mortar_integration.cpp.
#include <Eigen/Dense>
#include <cmath>
#include "engine/contact/mortar_integration.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/contact/integration_rules.hpp"
namespace lunaster::engine::contact::mortar {
bool transformed_slave(CellType t) { return t == CellType::Tria6 || t == CellType::Quad8; }
bool edge_vertices(CellType t, int a, int* v1, int* v2) {
  const int nv = surface_n_vertices(t);
  if (a < nv) return false;
  if (t == CellType::Seg3) { *v1 = 0; *v2 = 1; return true; }
  *v1 = a - nv; *v2 = (a - nv + 1) % nv; return true;
}
void slave_shape(CellType t, const double* xi, double* n) {
  surface_shape(t, xi, n, nullptr, nullptr);
  if (!transformed_slave(t)) return;
  const int nv = surface_n_vertices(t), nn = surface_n_nodes(t);
  double m[8]; for (int a = 0; a < nn; ++a) m[a] = n[a];
  for (int a = nv; a < nn; ++a) { int v1, v2; edge_vertices(t, a, &v1, &v2); n[v1] += kQuadraticAlpha * m[a]; n[v2] += kQuadraticAlpha * m[a]; n[a] = (1 - 2 * kQuadraticAlpha) * m[a]; }
}
static double project_seg(CellType t, const double* x, const double* p, const double* dir) {
  // xi with (x(xi) - p) x dir = 0 (2D cross)
  double xi[2] = {0, 0};
  for (int it = 0; it < 30; ++it) {
    SurfacePoint sp = surface_point(t, x, xi);
    double f = (sp.x[0] - p[0]) * dir[1] - (sp.x[1] - p[1]) * dir[0];
    double df = sp.t[0][0] * dir[1] - sp.t[0][1] * dir[0];
    if (df == 0) break;
    double d = f / df; xi[0] -= d; if (std::abs(d) < 1e-15) break;
  }
  return xi[0];
}
double overlap_points(CellType st, const double* sx, CellType mt, const double* mx, int degree, std::vector<OverlapPoint>& out) {
  double c[2] = {0, 0};
  SurfacePoint s0 = surface_point(st, sx, c), m0 = surface_point(mt, mx, c);
  if (s0.n[0] * m0.n[0] + s0.n[1] * m0.n[1] >= 0) return 0;
  // master ends projected on slave along slave normal at centre
  double a = project_seg(st, sx, mx, s0.n), b = project_seg(st, sx, mx + 3, s0.n);
  double lo = std::max(-1.0, std::min(a, b)), hi = std::min(1.0, std::max(a, b));
  if (hi - lo < 1e-12) return 0;
  int ng = (degree + 2) / 2;
  auto rule = contact_integration_rule(CellType::Seg2, IntegrationScheme::Gauss, ng);
  double total = 0;
  for (auto& q : rule) {
    OverlapPoint p; p.xi_s[0] = 0.5 * (lo + hi) + 0.5 * (hi - lo) * q.xi[0];
    SurfacePoint sp = surface_point(st, sx, p.xi_s);
    p.xi_m[0] = project_seg(mt, mx, sp.x, sp.n);
    p.w = q.weight * 0.5 * (hi - lo) * sp.jacobian;
    total += p.w; out.push_back(p);
  }
  return total;
}
bool dual_coefficients(CellType t, const std::vector<OverlapPoint>& pts, double* a) {
  const int n = surface_n_nodes(t);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n); Eigen::VectorXd D = Eigen::VectorXd::Zero(n);
  double N[8];
  for (auto& p : pts) { slave_shape(t, p.xi_s, N); for (int i = 0; i < n; ++i) { D[i] += p.w * N[i]; for (int j = 0; j < n; ++j) M(i, j) += p.w * N[i] * N[j]; } }
  for (int i = 0; i < n; ++i) if (!(D[i] > 0)) return false;
  Eigen::MatrixXd A = D.asDiagonal() * M.inverse();
  for (int i = 0; i < n; ++i) for (int j = 0; j < n; ++j) a[i * n + j] = A(i, j);
  return true;
}
}
