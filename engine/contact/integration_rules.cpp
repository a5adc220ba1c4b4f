#include "engine/contact/integration_rules.hpp"

#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "engine/contact/surface_element.hpp"
#include "engine/core/error.hpp"

namespace lunaster::engine::contact {

namespace {

using Rule = std::vector<ContactQuadPoint>;

ContactQuadPoint qp(double x, double y, double w) {
  ContactQuadPoint p;
  p.xi[0] = x, p.xi[1] = y, p.weight = w;
  return p;
}

// Gauss-Legendre on [-1,1], n = 1..6 (standard abscissae/weights).
Rule gauss_segment(int n) {
  static const double x[7][3] = {{},
                                 {0.0},
                                 {0.577350269189625764509149},
                                 {0.774596669241483377035853, 0.0},
                                 {0.861136311594052575223946, 0.339981043584856264802666},
                                 {0.906179845938663992797627, 0.538469310105683091036314, 0.0},
                                 {0.932469514203152027812302, 0.661209386466264513661400,
                                  0.238619186083196908630502}};
  static const double w[7][3] = {{},
                                 {2.0},
                                 {1.0},
                                 {5.0 / 9.0, 8.0 / 9.0},
                                 {0.347854845137453857373063, 0.652145154862546142626937},
                                 {0.236926885056189087514264, 0.478628670499366468041292, 128.0 / 225.0},
                                 {0.171324492379170345040296, 0.360761573048138607569834,
                                  0.467913934572691047389870}};
  Rule r;
  for (int k = 0; k < n / 2; ++k) r.push_back(qp(-x[n][k], 0, w[n][k]));
  if (n % 2) r.push_back(qp(0.0, 0, w[n][n / 2]));
  for (int k = n / 2 - 1; k >= 0; --k) r.push_back(qp(x[n][k], 0, w[n][k]));
  return r;
}

// Symmetric triangle rules with 1,3,4,6,7,12 points (degrees 1..6), reference area 1/2.
void add_orbit3(Rule& r, double a, double w) {  // (a, a), (1-2a, a), (a, 1-2a)
  r.push_back(qp(a, a, w)), r.push_back(qp(1 - 2 * a, a, w)), r.push_back(qp(a, 1 - 2 * a, w));
}
void add_orbit6(Rule& r, double a, double b, double w) {  // all permutations of (a, b, 1-a-b)
  const double c = 1 - a - b;
  r.push_back(qp(a, b, w)), r.push_back(qp(b, a, w)), r.push_back(qp(c, a, w));
  r.push_back(qp(c, b, w)), r.push_back(qp(a, c, w)), r.push_back(qp(b, c, w));
}

Rule gauss_triangle(int n) {
  Rule r;
  switch (n) {
    case 1: r.push_back(qp(1.0 / 3, 1.0 / 3, 0.5)); break;
    case 2: add_orbit3(r, 1.0 / 6, 1.0 / 6); break;
    case 3:
      add_orbit3(r, 0.2, 25.0 / 96);
      r.push_back(qp(1.0 / 3, 1.0 / 3, -27.0 / 96));
      break;
    case 4:
      add_orbit3(r, 0.091576213509770743, 0.054975871827660933);
      add_orbit3(r, 0.44594849091596488, 0.11169079483900573);
      break;
    case 5:
      r.push_back(qp(1.0 / 3, 1.0 / 3, 9.0 / 80));
      add_orbit3(r, 0.47014206410511509, 0.066197076394253090);
      add_orbit3(r, 0.10128650732345634, 0.062969590272413576);
      break;
    case 6:
      add_orbit3(r, 0.063089014491502228, 0.025422453185103409);
      add_orbit3(r, 0.24928674517091042, 0.058393137863189683);
      add_orbit6(r, 0.31035245103378440, 0.053145049844816947, 0.041425537809186787);
      break;
    default: LUNASTER_ASSERT(false, "Gauss triangle order out of range");
  }
  return r;
}

Rule tensor(const Rule& a) {
  Rule r;
  for (const auto& q : a)  // rows from the bottom left, as mmgaus
    for (const auto& p : a) r.push_back(qp(p.xi[0], q.xi[0], p.weight * q.weight));
  return r;
}

Rule newton_cotes_segment(int degree) {
  const std::vector<double> w = newton_cotes_weights(degree);
  Rule r;
  for (int i = 0; i <= degree; ++i) r.push_back(qp(-1.0 + 2.0 * i / degree, 0, w[i]));
  return r;
}

Rule simpson_segment() { return {qp(-1, 0, 1.0 / 3), qp(0, 0, 4.0 / 3), qp(1, 0, 1.0 / 3)}; }

// Base triangle rule of the composite Simpson scheme: vertices 1/40, mid-edges
// 1/15, centroid 9/40 (reference area 1/2). Like Simpson on a segment it samples
// the corners and mid-sides and integrates every cubic exactly (degree 3, not 4).
// code_aster's mmgaus weights the same lattice without a centroid (vertices 1/30,
// mid-edges 4/30): exact for linear functions only, which leaves LAGS_C on a
// TRIA6 slave 16 % (ORDRE_INT=4) to 49 % (ORDRE_INT=2) off in SSNP121 E.
Rule simpson_triangle() {
  Rule r = {qp(0, 0, 1.0 / 40), qp(1, 0, 1.0 / 40), qp(0, 1, 1.0 / 40)};
  r.push_back(qp(0.5, 0, 1.0 / 15)), r.push_back(qp(0.5, 0.5, 1.0 / 15)), r.push_back(qp(0, 0.5, 1.0 / 15));
  r.push_back(qp(1.0 / 3, 1.0 / 3, 9.0 / 40));
  return r;
}

Rule nodes_rule(CellType type) {
  switch (type) {
    case CellType::Seg2: return {qp(-1, 0, 1), qp(1, 0, 1)};
    case CellType::Seg3: return {qp(-1, 0, 0.5), qp(1, 0, 0.5), qp(0, 0, 1)};
    case CellType::Tria3: return {qp(0, 0, 1.0 / 6), qp(1, 0, 1.0 / 6), qp(0, 1, 1.0 / 6)};
    case CellType::Tria6: {  // trapezoid on the 4 sub-triangles: vertices 1/24, mid-edges 1/8
      Rule r = {qp(0, 0, 1.0 / 24), qp(1, 0, 1.0 / 24), qp(0, 1, 1.0 / 24)};
      r.push_back(qp(0.5, 0, 0.125)), r.push_back(qp(0.5, 0.5, 0.125)), r.push_back(qp(0, 0.5, 0.125));
      return r;
    }
    case CellType::Quad4: return {qp(-1, -1, 1), qp(1, -1, 1), qp(1, 1, 1), qp(-1, 1, 1)};
    case CellType::Quad8: {  // positive nodal weights, exact for bilinear fields
      Rule r = {qp(-1, -1, 1.0 / 3), qp(1, -1, 1.0 / 3), qp(1, 1, 1.0 / 3), qp(-1, 1, 1.0 / 3)};
      r.push_back(qp(0, -1, 2.0 / 3)), r.push_back(qp(1, 0, 2.0 / 3));
      r.push_back(qp(0, 1, 2.0 / 3)), r.push_back(qp(-1, 0, 2.0 / 3));
      return r;
    }
    default: LUNASTER_ASSERT(false, "not a contact surface cell type");
  }
  return {};
}

Rule auto_rule(CellType type) {
  switch (type) {
    case CellType::Seg2: return {qp(-1, 0, 1), qp(1, 0, 1)};
    case CellType::Seg3: return {qp(-1, 0, 1.0 / 3), qp(1, 0, 1.0 / 3), qp(0, 0, 4.0 / 3)};
    case CellType::Tria3: return {qp(0, 0, 1.0 / 6), qp(1, 0, 1.0 / 6), qp(0, 1, 1.0 / 6)};
    case CellType::Tria6: return gauss_triangle(4);
    case CellType::Quad4: return {qp(-1, -1, 1), qp(1, -1, 1), qp(1, 1, 1), qp(-1, 1, 1)};
    case CellType::Quad8: return tensor(simpson_segment());
    default: LUNASTER_ASSERT(false, "not a contact surface cell type");
  }
  return {};
}

// Composite rule: `base` applied on s (segment) or s^2 (triangle, quadrangle)
// equal sub-cells, coincident points merged.
Rule composite(CellType type, const Rule& base, int s) {
  if (s <= 1) return base;
  Rule all;
  const int rdim = surface_ref_dim(type);
  if (rdim == 1 || !is_triangle(type)) {
    const double h = 2.0 / s;
    const int ny = rdim == 1 ? 1 : s;
    const double scale = rdim == 1 ? 1.0 / s : 1.0 / (s * s);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < s; ++i)
        for (const auto& p : base) {
          const double x = -1 + h * i + 0.5 * h * (p.xi[0] + 1);
          const double y = rdim == 1 ? 0.0 : -1 + h * j + 0.5 * h * (p.xi[1] + 1);
          all.push_back(qp(x, y, p.weight * scale));
        }
  } else {
    const double h = 1.0 / s, scale = 1.0 / (s * s);
    for (int j = 0; j < s; ++j)
      for (int i = 0; i + j < s; ++i) {
        for (const auto& p : base)  // upright sub-triangle
          all.push_back(qp(h * (i + p.xi[0]), h * (j + p.xi[1]), p.weight * scale));
        if (i + j < s - 1)  // inverted one: vertex (i+1, j+1), edges towards -x and -y
          for (const auto& p : base)
            all.push_back(qp(h * (i + 1 - p.xi[1]), h * (j + 1 - p.xi[0]), p.weight * scale));
      }
  }
  Rule merged;
  for (const auto& p : all) {
    bool found = false;
    for (auto& m : merged)
      if (std::abs(m.xi[0] - p.xi[0]) < 1e-12 && std::abs(m.xi[1] - p.xi[1]) < 1e-12) {
        m.weight += p.weight, found = true;
        break;
      }
    if (!found) merged.push_back(p);
  }
  return merged;
}

}  // namespace

OrderRange integration_order_range(IntegrationScheme scheme) {
  switch (scheme) {
    case IntegrationScheme::Gauss: return {1, 6, 3};
    case IntegrationScheme::Simpson: return {1, 4, 1};
    case IntegrationScheme::NewtonCotes: return {3, 8, 3};
    default: return {0, 0, 0};
  }
}

std::vector<double> newton_cotes_weights(int degree) {
  // Closed Newton-Cotes: integral over n*h = h * C * sum c_i f_i (h = 2/n on [-1,1]).
  static const std::vector<std::vector<double>> c = {
      {},
      {1, 1},
      {1, 4, 1},
      {1, 3, 3, 1},
      {7, 32, 12, 32, 7},
      {19, 75, 50, 50, 75, 19},
      {41, 216, 27, 272, 27, 216, 41},
      {751, 3577, 1323, 2989, 2989, 1323, 3577, 751},
      {989, 5888, -928, 10496, -4540, 10496, -928, 5888, 989}};
  static const double factor[9] = {0, 1.0 / 2, 1.0 / 3, 3.0 / 8, 2.0 / 45, 5.0 / 288, 1.0 / 140, 7.0 / 17280,
                                   4.0 / 14175};
  LUNASTER_ASSERT(degree >= 1 && degree <= 8, "Newton-Cotes degree must be 1..8");
  std::vector<double> w;
  const double h = 2.0 / degree;
  for (double ci : c[degree]) w.push_back(h * factor[degree] * ci);
  return w;
}

std::vector<ContactQuadPoint> triangle_newton_cotes(int degree) {
  // Interpolatory weights: sum_p w_p x_p^a y_p^b = a! b! / (a+b+2)! for a+b <= n.
  Rule pts;
  for (int j = 0; j <= degree; ++j)
    for (int i = 0; i + j <= degree; ++i) pts.push_back(qp(double(i) / degree, double(j) / degree, 0));
  const int np = static_cast<int>(pts.size());
  Eigen::MatrixXd v(np, np);
  Eigen::VectorXd m(np);
  int row = 0;
  for (int a = 0; a <= degree; ++a)
    for (int b = 0; a + b <= degree; ++b, ++row) {
      for (int p = 0; p < np; ++p) v(row, p) = std::pow(pts[p].xi[0], a) * std::pow(pts[p].xi[1], b);
      m(row) = std::tgamma(a + 1.0) * std::tgamma(b + 1.0) / std::tgamma(a + b + 3.0);
    }
  const Eigen::VectorXd w = v.fullPivLu().solve(m);
  for (int p = 0; p < np; ++p) pts[p].weight = w(p);
  return pts;
}

std::vector<ContactQuadPoint> contact_integration_rule(CellType type, IntegrationScheme scheme, int order,
                                                       int sub_elements) {
  LUNASTER_ASSERT(is_surface_type(type), "contact integration on a non-surface cell");
  const OrderRange range = integration_order_range(scheme);
  if (range.max > 0) {
    if (order == 0) order = range.default_order;
    if (order < range.min || order > range.max)
      throw DeckError("contact integration order " + std::to_string(order) + " outside " +
                      std::to_string(range.min) + ".." + std::to_string(range.max) + " for this scheme");
  }
  if (sub_elements < 1) throw DeckError("contact integration: sub_elements must be >= 1");
  const bool seg = surface_ref_dim(type) == 1, tri = is_triangle(type);
  Rule base;
  switch (scheme) {
    case IntegrationScheme::Auto: base = auto_rule(type); break;
    case IntegrationScheme::Nodes: base = nodes_rule(type); break;
    case IntegrationScheme::Gauss:
      base = seg ? gauss_segment(order) : tri ? gauss_triangle(order) : tensor(gauss_segment(order));
      break;
    case IntegrationScheme::Simpson:
      // m subdivisions = composite of the basic rule over m sub-cells.
      base = seg ? composite(type, simpson_segment(), order)
                 : tri ? composite(type, simpson_triangle(), order)
                       : tensor(composite(CellType::Seg2, simpson_segment(), order));
      break;
    case IntegrationScheme::NewtonCotes:
      base = seg ? newton_cotes_segment(order) : tri ? triangle_newton_cotes(order)
                                                     : tensor(newton_cotes_segment(order));
      break;
  }
  return composite(type, base, sub_elements);
}

}  // namespace lunaster::engine::contact
