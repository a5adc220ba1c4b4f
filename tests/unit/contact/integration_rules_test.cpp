// Contact integration rules: weights, point counts, exactness, tabulated values.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/contact/integration_rules.hpp"
#include "engine/core/error.hpp"

using namespace lunaster::engine;
using namespace lunaster::engine::contact;

namespace {

double integrate(const std::vector<ContactQuadPoint>& rule, int px, int py) {
  double s = 0.0;
  for (const auto& q : rule) s += q.weight * std::pow(q.xi[0], px) * std::pow(q.xi[1], py);
  return s;
}

// Exact integrals of x^a y^b on the reference cells.
double exact_segment(int a) { return a % 2 ? 0.0 : 2.0 / (a + 1); }
double exact_quad(int a, int b) { return exact_segment(a) * exact_segment(b); }
double exact_triangle(int a, int b) { return std::tgamma(a + 1.0) * std::tgamma(b + 1.0) / std::tgamma(a + b + 3.0); }

double sum_weights(const std::vector<ContactQuadPoint>& rule) { return integrate(rule, 0, 0); }

const CellType kAll[] = {CellType::Seg2, CellType::Seg3, CellType::Tria3, CellType::Tria6, CellType::Quad4,
                         CellType::Quad8};

double measure(CellType t) {
  return (t == CellType::Seg2 || t == CellType::Seg3) ? 2.0 : (t == CellType::Tria3 || t == CellType::Tria6) ? 0.5 : 4.0;
}

}  // namespace

TEST(ContactIntegration, WeightsSumToReferenceMeasure) {
  for (CellType t : kAll) {
    for (IntegrationScheme s : {IntegrationScheme::Auto, IntegrationScheme::Nodes})
      for (int sub = 1; sub <= 3; ++sub)
        EXPECT_NEAR(sum_weights(contact_integration_rule(t, s, 0, sub)), measure(t), 1e-13);
    for (IntegrationScheme s : {IntegrationScheme::Gauss, IntegrationScheme::Simpson, IntegrationScheme::NewtonCotes}) {
      const OrderRange r = integration_order_range(s);
      for (int order = r.min; order <= r.max; ++order)
        for (int sub = 1; sub <= 2; ++sub)
          EXPECT_NEAR(sum_weights(contact_integration_rule(t, s, order, sub)), measure(t), 1e-12)
              << "scheme " << int(s) << " order " << order;
    }
  }
}

TEST(ContactIntegration, PointCountsFollowCodeAster) {
  const int simpson_seg[] = {3, 5, 7, 9}, simpson_tri[] = {6, 15, 28, 45}, simpson_quad[] = {9, 25, 49, 81};
  for (int m = 1; m <= 4; ++m) {
    EXPECT_EQ(contact_integration_rule(CellType::Seg2, IntegrationScheme::Simpson, m).size(), size_t(simpson_seg[m - 1]));
    EXPECT_EQ(contact_integration_rule(CellType::Tria6, IntegrationScheme::Simpson, m).size(), size_t(simpson_tri[m - 1]));
    EXPECT_EQ(contact_integration_rule(CellType::Quad8, IntegrationScheme::Simpson, m).size(), size_t(simpson_quad[m - 1]));
  }
  const int gauss_tri[] = {1, 3, 4, 6, 7, 12};
  for (int n = 1; n <= 6; ++n) {
    EXPECT_EQ(contact_integration_rule(CellType::Seg3, IntegrationScheme::Gauss, n).size(), size_t(n));
    EXPECT_EQ(contact_integration_rule(CellType::Tria3, IntegrationScheme::Gauss, n).size(), size_t(gauss_tri[n - 1]));
    EXPECT_EQ(contact_integration_rule(CellType::Quad4, IntegrationScheme::Gauss, n).size(), size_t(n * n));
  }
  for (int n = 3; n <= 8; ++n) {
    EXPECT_EQ(contact_integration_rule(CellType::Seg2, IntegrationScheme::NewtonCotes, n).size(), size_t(n + 1));
    EXPECT_EQ(contact_integration_rule(CellType::Tria6, IntegrationScheme::NewtonCotes, n).size(),
              size_t((n + 1) * (n + 2) / 2));
  }
  // SSNP121 A: SIMPSON, ORDRE_INT=4 -> 9 points per SEG2 at xi = -1 + k/4.
  const auto a = contact_integration_rule(CellType::Seg2, IntegrationScheme::Simpson, 4);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(a[k].xi[0], -1.0 + k / 4.0, 1e-15);
  EXPECT_NEAR(a[0].weight, 1.0 / 12, 1e-15);
  EXPECT_NEAR(a[1].weight, 4.0 / 12, 1e-15);
  EXPECT_NEAR(a[2].weight, 2.0 / 12, 1e-15);
  // Sub-elements: SIMPSON order 1 on 3 sub-elements = composite Simpson with 7 points.
  EXPECT_EQ(contact_integration_rule(CellType::Seg2, IntegrationScheme::Simpson, 1, 3).size(), 7u);
  EXPECT_EQ(contact_integration_rule(CellType::Tria3, IntegrationScheme::Simpson, 1, 2).size(), 15u);
}

TEST(ContactIntegration, SegmentExactness) {
  for (int n = 1; n <= 6; ++n) {
    const auto r = contact_integration_rule(CellType::Seg2, IntegrationScheme::Gauss, n);
    for (int a = 0; a <= 2 * n - 1; ++a) EXPECT_NEAR(integrate(r, a, 0), exact_segment(a), 1e-13) << n << " " << a;
    EXPECT_GT(std::abs(integrate(r, 2 * n, 0) - exact_segment(2 * n)), 1e-6);
  }
  for (int m = 1; m <= 4; ++m) {
    const auto r = contact_integration_rule(CellType::Seg2, IntegrationScheme::Simpson, m);
    for (int a = 0; a <= 3; ++a) EXPECT_NEAR(integrate(r, a, 0), exact_segment(a), 1e-13);
  }
  for (int n = 3; n <= 8; ++n) {
    const auto r = contact_integration_rule(CellType::Seg2, IntegrationScheme::NewtonCotes, n);
    const int degree = n % 2 ? n : n + 1;
    for (int a = 0; a <= degree; ++a) EXPECT_NEAR(integrate(r, a, 0), exact_segment(a), 1e-13) << n << " " << a;
  }
}

TEST(ContactIntegration, NewtonCotesDegree8HasTabulatedNegativeWeights) {
  // code_aster mmgaus table pncseg(8,*) on [-1,1].
  const std::vector<double> w = newton_cotes_weights(8);
  ASSERT_EQ(w.size(), 9u);
  EXPECT_NEAR(w[0], 0.069770723104057, 1e-14);
  EXPECT_NEAR(w[1], 0.415379188712522, 1e-14);
  EXPECT_NEAR(w[2], -0.065467372134039, 1e-14);
  EXPECT_NEAR(w[3], 0.740458553791887, 1e-14);
  EXPECT_NEAR(w[4], -0.320282186948854, 1e-14);
  EXPECT_NEAR(w[8], w[0], 1e-15);
}

TEST(ContactIntegration, TriangleRulesExactness) {
  for (int n = 1; n <= 6; ++n) {
    const auto r = contact_integration_rule(CellType::Tria3, IntegrationScheme::Gauss, n);
    for (int a = 0; a <= n; ++a)
      for (int b = 0; a + b <= n; ++b) EXPECT_NEAR(integrate(r, a, b), exact_triangle(a, b), 1e-12) << n;
  }
  for (int n = 3; n <= 8; ++n) {
    const auto r = contact_integration_rule(CellType::Tria6, IntegrationScheme::NewtonCotes, n);
    for (int a = 0; a <= n; ++a)
      for (int b = 0; a + b <= n; ++b) EXPECT_NEAR(integrate(r, a, b), exact_triangle(a, b), 1e-11) << n;
  }
  // Values of code_aster's pnctri table: degree 3 vertex / edge / centre, degree 8 centre orbit.
  const auto t3 = triangle_newton_cotes(3);
  EXPECT_NEAR(t3[0].weight, 0.016666666666667, 1e-12);  // (0,0)
  EXPECT_NEAR(t3[1].weight, 0.0375, 1e-12);             // (1/3,0)
  EXPECT_NEAR(t3[5].weight, 0.225, 1e-12);              // (1/3,1/3)
  const auto t4 = triangle_newton_cotes(4);
  EXPECT_NEAR(t4[0].weight, 0.0, 1e-12);
  EXPECT_NEAR(t4[2].weight, -0.011111111111111, 1e-12);  // (1/2,0)
  // Composite Simpson on triangles has code_aster's weights: (1, 4, 3, 6, 8)/(30 m^2).
  const auto s2 = contact_integration_rule(CellType::Tria3, IntegrationScheme::Simpson, 2);
  double wmin = 1, wmax = 0;
  for (const auto& q : s2) wmin = std::min(wmin, q.weight), wmax = std::max(wmax, q.weight);
  EXPECT_NEAR(wmin, 1.0 / 120, 1e-15);
  EXPECT_NEAR(wmax, 8.0 / 120, 1e-15);
}

TEST(ContactIntegration, QuadrangleRulesExactness) {
  for (int n = 1; n <= 6; ++n) {
    const auto r = contact_integration_rule(CellType::Quad8, IntegrationScheme::Gauss, n);
    for (int a = 0; a <= 2 * n - 1; ++a)
      for (int b = 0; b <= 2 * n - 1; ++b) EXPECT_NEAR(integrate(r, a, b), exact_quad(a, b), 1e-12);
  }
  const auto autoq8 = contact_integration_rule(CellType::Quad8, IntegrationScheme::Auto, 0);
  ASSERT_EQ(autoq8.size(), 9u);
  EXPECT_NEAR(integrate(autoq8, 2, 2), exact_quad(2, 2), 1e-13);
}

TEST(ContactIntegration, OrderOutsideRangeIsAnInputError) {
  EXPECT_THROW(contact_integration_rule(CellType::Seg2, IntegrationScheme::Simpson, 5), lunaster::DeckError);
  EXPECT_THROW(contact_integration_rule(CellType::Seg2, IntegrationScheme::NewtonCotes, 2), lunaster::DeckError);
  EXPECT_THROW(contact_integration_rule(CellType::Seg2, IntegrationScheme::Gauss, 7), lunaster::DeckError);
}
