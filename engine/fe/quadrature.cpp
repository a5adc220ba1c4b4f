/// Quadrature rules: Gauss-Legendre on segments and products, symmetric rules
/// on triangles (Strang-Fix/Dunavant) and tetrahedra (Keast/Walkington), and
/// triangle x Gauss products on prisms. Reference cells as in shape.hpp.
#include "engine/fe/quadrature.hpp"

#include <array>
#include <cmath>
#include <mutex>

#include "engine/core/error.hpp"

namespace lunaster::engine {
namespace {

// Gauss-Legendre nodes by Newton iteration on P_n (Abramowitz-Stegun 25.4.29).
std::vector<QuadraturePoint> compute_gauss_legendre(int n) {
  std::vector<QuadraturePoint> pts(n);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0, p1 = x;
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // recompute derivative at the converged root for the weight
    double p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (x * p1 - p0) / (x * x - 1);
    pts[n - 1 - i].xi[0] = x;  // ascending order
    pts[n - 1 - i].weight = 2.0 / ((1 - x * x) * dp * dp);
  }
  return pts;
}

void add(std::vector<QuadraturePoint>& r, double a, double b, double c, double w) {
  QuadraturePoint q;
  q.xi[0] = a;
  q.xi[1] = b;
  q.xi[2] = c;
  q.weight = w;
  r.push_back(q);
}

/// Triangle (0,0),(1,0),(0,1): 1 point (degree 1), 3 points (degree 2), 6 points (degree 4).
std::vector<QuadraturePoint> triangle(int n_points) {
  std::vector<QuadraturePoint> r;
  if (n_points == 1) {
    add(r, 1.0 / 3, 1.0 / 3, 0, 0.5);
  } else if (n_points == 3) {
    add(r, 1.0 / 6, 1.0 / 6, 0, 1.0 / 6);
    add(r, 2.0 / 3, 1.0 / 6, 0, 1.0 / 6);
    add(r, 1.0 / 6, 2.0 / 3, 0, 1.0 / 6);
  } else {
    const double a = 0.445948490915965, wa = 0.223381589678011 / 2;
    const double b = 0.091576213509771, wb = 0.109951743655322 / 2;
    for (auto [p, w] : {std::pair{a, wa}, std::pair{b, wb}}) {
      add(r, p, p, 0, w);
      add(r, 1 - 2 * p, p, 0, w);
      add(r, p, 1 - 2 * p, 0, w);
    }
  }
  return r;
}

/// Tetrahedron (unit simplex): 4 points (degree 2) or 14 points (degree 5).
std::vector<QuadraturePoint> tetrahedron(int n_points) {
  std::vector<QuadraturePoint> r;
  auto four = [&](double a, double w) {  // permutations of (a, a, a, 1-3a)
    const double b = 1 - 3 * a;
    add(r, a, a, a, w);
    add(r, b, a, a, w);
    add(r, a, b, a, w);
    add(r, a, a, b, w);
  };
  if (n_points == 4) {
    four(0.1381966011250105, 1.0 / 24);
    return r;
  }
  four(0.0927352503108912, 0.01224884051939366);
  four(0.3108859192633006, 0.01878132095300264);
  const double c = 0.4544962958743504, d = 0.5 - c, w = 0.007091003462846911;
  add(r, c, c, d, w);
  add(r, c, d, c, w);
  add(r, d, c, c, w);
  add(r, d, d, c, w);
  add(r, d, c, d, w);
  add(r, c, d, d, w);
  return r;
}

std::vector<QuadraturePoint> product(const std::vector<QuadraturePoint>& a, const std::vector<QuadraturePoint>& b,
                                     int dim_a) {
  std::vector<QuadraturePoint> r;
  for (const auto& qb : b)
    for (const auto& qa : a) {
      QuadraturePoint q = qa;
      q.xi[dim_a] = qb.xi[0];
      q.weight = qa.weight * qb.weight;
      r.push_back(q);
    }
  return r;
}

std::vector<QuadraturePoint> build_rule(CellType type) {
  const auto g = [](int n) { return gauss_legendre(n); };
  switch (type) {
    case CellType::Point1: { std::vector<QuadraturePoint> r; add(r, 0, 0, 0, 1); return r; }
    case CellType::Seg2: return g(2);
    case CellType::Seg3: return g(3);
    case CellType::Tria3: return triangle(3);
    case CellType::Tria6: return triangle(6);
    case CellType::Quad4: return product(g(2), g(2), 1);
    case CellType::Quad8: return product(g(3), g(3), 1);
    case CellType::Tetra4: return tetrahedron(4);
    case CellType::Tetra10: return tetrahedron(14);
    case CellType::Penta6: return product(triangle(3), g(2), 2);
    case CellType::Penta15: return product(triangle(6), g(3), 2);
    case CellType::Hexa8: return product(product(g(2), g(2), 1), g(2), 2);
    case CellType::Hexa20: return product(product(g(3), g(3), 1), g(3), 2);
    default: break;
  }
  throw InternalError("full_integration: no rule for this cell type");
}

}  // namespace

std::vector<QuadraturePoint> gauss_legendre(int n) {
  LUNASTER_ASSERT(n >= 1 && n <= 10, "gauss_legendre: n must be in 1..10");
  if (n == 1) {
    std::vector<QuadraturePoint> r(1);
    r[0].weight = 2.0;
    return r;
  }
  return compute_gauss_legendre(n);
}

const std::vector<QuadraturePoint>& full_integration(CellType type) {
  static std::array<std::vector<QuadraturePoint>, kCellTypeCount> rules;
  static std::array<std::once_flag, kCellTypeCount> once;
  const int t = static_cast<int>(type);
  std::call_once(once[t], [&] { rules[t] = build_rule(type); });
  return rules[t];
}

}  // namespace lunaster::engine
