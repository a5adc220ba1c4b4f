// Shape functions (partition of unity, Kronecker property, derivatives by
// finite differences, orientation of MED cells) and quadrature exactness.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

#include "engine/fe/quadrature.hpp"
#include "engine/fe/reference_element.hpp"
#include "engine/fe/shape.hpp"
#include "fe_test_util.hpp"

namespace lunaster::engine {
namespace {

using test::expect_close;
using test::type_name;

const std::vector<CellType> kAll = {CellType::Seg2,   CellType::Seg3,    CellType::Tria3,  CellType::Tria6,
                                    CellType::Quad4,  CellType::Quad8,   CellType::Tetra4, CellType::Tetra10,
                                    CellType::Penta6, CellType::Penta15, CellType::Hexa8,  CellType::Hexa20};

/// A point inside every reference cell.
void interior_point(CellType t, double* xi) {
  xi[0] = 0.21, xi[1] = 0.17, xi[2] = 0.13;
  if (t == CellType::Seg2 || t == CellType::Seg3) xi[0] = -0.37;
  if (t == CellType::Quad4 || t == CellType::Quad8 || t == CellType::Hexa8 || t == CellType::Hexa20)
    xi[0] = -0.37, xi[1] = 0.61, xi[2] = -0.23;
  if (t == CellType::Penta6 || t == CellType::Penta15) xi[2] = -0.44;
}

TEST(Shape, PartitionOfUnityAndKronecker) {
  for (CellType t : kAll) {
    const int nn = cell_n_nodes(t), dim = cell_dim(t);
    double n[kMaxCellNodes], dn[kMaxCellNodes * 3], xi[3];
    interior_point(t, xi);
    shape_functions(t, xi, n, dn);
    double sum = 0, dsum[3] = {0, 0, 0};
    for (int a = 0; a < nn; ++a) {
      sum += n[a];
      for (int k = 0; k < dim; ++k) dsum[k] += dn[a * dim + k];
    }
    expect_close(sum, 1.0, 1e-14, 1e-14, type_name(t) + " sum N");
    for (int k = 0; k < dim; ++k) expect_close(dsum[k], 0.0, 0, 1e-13, type_name(t) + " sum dN");
    for (int b = 0; b < nn; ++b) {
      double xb[3] = {0, 0, 0};
      reference_node(t, b, xb);
      shape_functions(t, xb, n, nullptr);
      for (int a = 0; a < nn; ++a)
        expect_close(n[a], a == b ? 1.0 : 0.0, 0, 1e-14, type_name(t) + " N_" + std::to_string(a) + " at node " + std::to_string(b));
    }
  }
}

TEST(Shape, DerivativesMatchFiniteDifferences) {
  for (CellType t : kAll) {
    const int nn = cell_n_nodes(t), dim = cell_dim(t);
    double xi[3], n_plus[kMaxCellNodes], n_minus[kMaxCellNodes], dn[kMaxCellNodes * 3];
    interior_point(t, xi);
    shape_functions(t, xi, nullptr, dn);
    const double h = 1e-6;
    for (int k = 0; k < dim; ++k) {
      double xp[3] = {xi[0], xi[1], xi[2]}, xm[3] = {xi[0], xi[1], xi[2]};
      xp[k] += h;
      xm[k] -= h;
      shape_functions(t, xp, n_plus, nullptr);
      shape_functions(t, xm, n_minus, nullptr);
      for (int a = 0; a < nn; ++a)
        expect_close(dn[a * dim + k], (n_plus[a] - n_minus[a]) / (2 * h), 1e-8, 1e-8,
                     type_name(t) + " dN_" + std::to_string(a) + "/dxi_" + std::to_string(k));
    }
  }
}

TEST(Shape, ReproducesLinearAndQuadraticFields) {
  // Isoparametric completeness: sum N_a f(xi_a) = f(xi) for f linear (all), quadratic (Lagrange P2 types).
  for (CellType t : kAll) {
    const int nn = cell_n_nodes(t), dim = cell_dim(t);
    auto lin = [](const double* x) { return 0.3 + 1.1 * x[0] - 0.7 * x[1] + 0.4 * x[2]; };
    double xi[3], n[kMaxCellNodes];
    interior_point(t, xi);
    shape_functions(t, xi, n, nullptr);
    double v = 0;
    for (int a = 0; a < nn; ++a) {
      double xa[3] = {0, 0, 0};
      reference_node(t, a, xa);
      v += n[a] * lin(xa);
    }
    double xc[3] = {xi[0], dim > 1 ? xi[1] : 0.0, dim > 2 ? xi[2] : 0.0};
    expect_close(v, lin(xc), 1e-13, 1e-13, type_name(t) + " linear field");
  }
}

// VTK reference cells (vtk node order) of tetra, wedge and hexa, linear and
// quadratic, converted to MED with the permutations of shared/spec/med-facts.md:
// the isoparametric map must be affine (constant J) with det J > 0.
struct VtkCell {
  CellType type;
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::pair<int, int>> mid_edges;
  std::vector<int> vtk_to_med;  // vtk[i] = med[p[i]]
};

std::vector<VtkCell> vtk_cells() {
  const std::vector<std::array<double, 3>> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::array<double, 3>> hex = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  // wedge with its first face's right-hand normal pointing away from the top face (VTK's documented rule)
  const std::vector<std::array<double, 3>> wedge = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
  const std::vector<std::pair<int, int>> tet_e = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  const std::vector<std::pair<int, int>> hex_e = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  const std::vector<std::pair<int, int>> wedge_e = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
  std::vector<int> id6(6), id15(15);
  for (int i = 0; i < 15; ++i) (i < 6 ? id6[i] = i : 0), id15[i] = i;
  return {
      {CellType::Tetra4, tet, {}, {0, 2, 1, 3}},
      {CellType::Tetra10, tet, tet_e, {0, 2, 1, 3, 6, 5, 4, 7, 9, 8}},
      {CellType::Hexa8, hex, {}, {0, 3, 2, 1, 4, 7, 6, 5}},
      {CellType::Hexa20, hex, hex_e, {0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 15, 14, 13, 12, 16, 19, 18, 17}},
      {CellType::Penta6, wedge, {}, id6},
      {CellType::Penta15, wedge, wedge_e, id15},
  };
}

TEST(Shape, MedCellsFromVtkHavePositiveConstantJacobian) {
  for (const VtkCell& c : vtk_cells()) {
    std::vector<std::array<double, 3>> vtk = c.vertices;
    for (auto [a, b] : c.mid_edges) {
      std::array<double, 3> m;
      for (int d = 0; d < 3; ++d) m[d] = 0.5 * (c.vertices[a][d] + c.vertices[b][d]);
      vtk.push_back(m);
    }
    const int nn = cell_n_nodes(c.type);
    ASSERT_EQ(static_cast<int>(vtk.size()), nn);
    std::vector<std::array<double, 3>> med(nn);
    for (int i = 0; i < nn; ++i) med[c.vtk_to_med[i]] = vtk[i];
    Eigen::Matrix3d j0;
    for (int q = 0; q < 3; ++q) {
      double xi[3] = {0.1 + 0.2 * q, 0.2, -0.3 + 0.25 * q}, dn[kMaxCellNodes * 3];
      if (c.type == CellType::Tetra4 || c.type == CellType::Tetra10) xi[2] = 0.1 * q;
      shape_functions(c.type, xi, nullptr, dn);
      Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
      for (int a = 0; a < nn; ++a)
        for (int r = 0; r < 3; ++r)
          for (int k = 0; k < 3; ++k) j(r, k) += med[a][r] * dn[a * 3 + k];
      EXPECT_GT(j.determinant(), 0.0) << type_name(c.type);
      if (q == 0) j0 = j;
      EXPECT_LT((j - j0).norm(), 1e-13) << type_name(c.type) << ": map not affine, mid-side order wrong";
    }
  }
}

double monomial_integral_simplex(int dim, const int* p) {
  // int over the unit simplex of x^a y^b z^c = a! b! c! / (a+b+c+dim)!
  double num = 1, s = dim;
  for (int k = 0; k < dim; ++k) {
    for (int i = 2; i <= p[k]; ++i) num *= i;
    s += p[k];
  }
  double den = 1;
  for (int i = 2; i <= s; ++i) den *= i;
  return num / den;
}

double line_integral(int p) { return p % 2 ? 0.0 : 2.0 / (p + 1); }

TEST(Quadrature, GaussLegendreExactToDegree2nMinus1) {
  for (int n = 1; n <= 10; ++n) {
    const auto q = gauss_legendre(n);
    ASSERT_EQ(static_cast<int>(q.size()), n);
    for (int p = 0; p <= 2 * n - 1; ++p) {
      double s = 0;
      for (const auto& pt : q) s += pt.weight * std::pow(pt.xi[0], p);
      expect_close(s, line_integral(p), 1e-13, 1e-14, "GL" + std::to_string(n) + " x^" + std::to_string(p));
    }
  }
}

struct RuleCase {
  CellType type;
  int degree;
};

double exact(CellType t, const int* p) {
  switch (t) {
    case CellType::Tria3: case CellType::Tria6: return monomial_integral_simplex(2, p);
    case CellType::Tetra4: case CellType::Tetra10: return monomial_integral_simplex(3, p);
    case CellType::Quad4: case CellType::Quad8: return line_integral(p[0]) * line_integral(p[1]);
    case CellType::Hexa8: case CellType::Hexa20: return line_integral(p[0]) * line_integral(p[1]) * line_integral(p[2]);
    case CellType::Penta6: case CellType::Penta15: return monomial_integral_simplex(2, p) * line_integral(p[2]);
    default: return line_integral(p[0]);
  }
}

TEST(Quadrature, FullIntegrationExactness) {
  // degree: total degree on simplices, per-direction degree on products
  const RuleCase cases[] = {{CellType::Seg2, 3},   {CellType::Seg3, 5},    {CellType::Tria3, 2},  {CellType::Tria6, 4},
                            {CellType::Quad4, 3},  {CellType::Quad8, 5},   {CellType::Tetra4, 2}, {CellType::Tetra10, 5},
                            {CellType::Penta6, 2}, {CellType::Penta15, 4}, {CellType::Hexa8, 3},  {CellType::Hexa20, 5}};
  for (const auto& rc : cases) {
    const auto& rule = full_integration(rc.type);
    const int dim = cell_dim(rc.type);
    const bool simplex_part = rc.type == CellType::Tria3 || rc.type == CellType::Tria6 || rc.type == CellType::Tetra4 ||
                              rc.type == CellType::Tetra10 || rc.type == CellType::Penta6 || rc.type == CellType::Penta15;
    int tested = 0;
    for (int a = 0; a <= rc.degree; ++a)
      for (int b = 0; b <= (dim > 1 ? rc.degree : 0); ++b)
        for (int c = 0; c <= (dim > 2 ? rc.degree : 0); ++c) {
          int p[3] = {a, b, c};
          if (simplex_part) {
            const bool prism = rc.type == CellType::Penta6 || rc.type == CellType::Penta15;
            if (a + b + (prism ? 0 : c) > rc.degree) continue;
            if (prism && c > (rc.type == CellType::Penta6 ? 3 : 5)) continue;
          }
          double s = 0;
          for (const auto& q : rule) s += q.weight * std::pow(q.xi[0], a) * std::pow(q.xi[1], b) * std::pow(q.xi[2], c);
          expect_close(s, exact(rc.type, p), 1e-12, 1e-14,
                       type_name(rc.type) + " x^" + std::to_string(a) + " y^" + std::to_string(b) + " z^" + std::to_string(c));
          ++tested;
        }
    EXPECT_GT(tested, 1);
  }
}

TEST(Quadrature, RulesHaveTheDocumentedSizes) {
  EXPECT_EQ(full_integration(CellType::Quad4).size(), 4u);
  EXPECT_EQ(full_integration(CellType::Quad8).size(), 9u);
  EXPECT_EQ(full_integration(CellType::Tria6).size(), 6u);
  EXPECT_EQ(full_integration(CellType::Hexa20).size(), 27u);
  EXPECT_EQ(full_integration(CellType::Penta15).size(), 18u);
  EXPECT_EQ(full_integration(CellType::Tetra10).size(), 14u);
}

TEST(ReferenceElement, ExtrapolationReproducesLinearFields) {
  // Extrapolating Gauss values of a field of the linear space gives its nodal values.
  for (CellType t : kAll) {
    const ReferenceElement& re = reference_element(t);
    const auto& rule = full_integration(t);
    auto f = [](const double* x) { return 2.0 - 0.5 * x[0] + 0.25 * x[1] + 0.125 * x[2]; };
    for (int a = 0; a < re.n_nodes; ++a) {
      double xa[3] = {0, 0, 0};
      reference_node(t, a, xa);
      double v = 0;
      for (int q = 0; q < re.n_qp; ++q) {
        double xq[3] = {rule[q].xi[0], re.dim > 1 ? rule[q].xi[1] : 0.0, re.dim > 2 ? rule[q].xi[2] : 0.0};
        v += re.extrapolation[static_cast<size_t>(a) * re.n_qp + q] * f(xq);
      }
      expect_close(v, f(xa), 1e-12, 1e-12, type_name(t) + " node " + std::to_string(a));
    }
  }
}

}  // namespace
}  // namespace lunaster::engine
