// Coulomb friction on the engine's frictionless laws (coulomb_law.hpp): for the augmented
// Lagrangian (tractions as multipliers) and the penalty friction on the continuous laws and the
// nodal springs, in 2D and 3D, the residual and tangent blocks match central finite differences
// inside each status; the statuses are those of Coulomb's law on chosen inputs; the slip
// branch carries exactly mu times the normal force along the slip; the penalty keeps its
// traction as history.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/contact/coulomb_law.hpp"
#include "point_law_unknowns.hpp"

namespace coulomb_law_test {

using namespace lunaster::engine;
using namespace lunaster::engine::contact;

constexpr double kMu = 0.3, kWeight = 0.25;

struct Case {
  const char* name;
  ContactEnforcement normal;
  FrictionEnforcement friction;
  double rho, coefficient_t;
  bool nodal;
};

// Coefficients in the units each law takes: rho (Pa/m) and COEF_FROT (Pa/m) for the augmented
// Lagrangian, COEF_PENA_CONT / COEF_PENA_FROT (Pa/m), E_N / E_T (N/m).
const Case kCases[] = {
    {"augmented Lagrangian", ContactEnforcement::AugmentedLagrangian, FrictionEnforcement::AugmentedLagrangian, 1e10,
     3e9, false},
    {"penalty", ContactEnforcement::Penalty, FrictionEnforcement::Penalty, 1e10, 2e9, false},
    {"penalty normal, multipliers", ContactEnforcement::Penalty, FrictionEnforcement::AugmentedLagrangian, 1e10, 3e9,
     false},
    {"springs", ContactEnforcement::Springs, FrictionEnforcement::Penalty, 1e10, 2e9, true},
};

// The point's unknowns: q = (g, s1[, s2]) and z = the law's multipliers.
PointKinematics at(int dim, const Case& c, int n_z, double g, const std::vector<double>& slip,
                   const std::vector<double>& z) {
  PointKinematics in;
  in.n_tangents = dim - 1;
  in.q[0] = g;
  for (int k = 0; k < dim - 1; ++k) in.q[1 + k] = in.dq_step[1 + k] = slip[k];
  for (int k = 0; k < n_z; ++k) in.z[k] = z[k];
  in.weight = kWeight;
  in.coefficient = c.rho;
  in.mu = kMu;
  in.coefficient_t = c.coefficient_t;
  return in;
}

double residual(const PointResponse& r, int row) { return point_law_unknowns::residual(r, r.n_q, row); }
double tangent(const PointResponse& r, int row, int col) { return point_law_unknowns::tangent(r, r.n_q, row, col); }
using point_law_unknowns::perturb;

PointResponse evaluate(const PointLaw& law, const PointKinematics& in, const PointState& start, bool closed) {
  PointState state;
  state.status = closed ? PointStatus::Stick : PointStatus::Open;
  return law.evaluate(in, start, state);
}

void expect_tangent(const PointLaw& law, const PointKinematics& in, const PointState& start, PointStatus expected) {
  const PointResponse r = evaluate(law, in, start, true);
  ASSERT_EQ(r.status, expected);
  const int n = r.n_q + r.n_z;
  for (int j = 0; j < n; ++j) {
    const double h = j < r.n_q ? 1e-11 : 1e-1;  // gaps ~ 1e-5 m, multipliers ~ 1e6 Pa
    PointKinematics plus = in, minus = in;
    perturb(plus, r.n_q, j, h);
    perturb(minus, r.n_q, j, -h);
    const PointResponse rp = evaluate(law, plus, start, true), rm = evaluate(law, minus, start, true);
    ASSERT_EQ(rp.status, expected);
    ASSERT_EQ(rm.status, expected);
    double column = 0.0;
    for (int i = 0; i < n; ++i) column = std::max(column, std::abs(tangent(r, i, j)));
    for (int i = 0; i < n; ++i) {
      const double fd = (residual(rp, i) - residual(rm, i)) / (2.0 * h);
      EXPECT_NEAR(tangent(r, i, j), fd, 1e-6 * column + 1e-12) << "row " << i << ", column " << j;
    }
  }
}

TEST(CoulombLaw, BlocksMatchFiniteDifferencesInStickAndSlip) {
  for (const Case& c : kCases)
    for (int dim : {2, 3}) {
      SCOPED_TRACE(std::string(c.name) + ", dim " + std::to_string(dim));
      const auto normal = make_contact_law(c.normal);
      const auto law = make_coulomb_law(*normal, c.friction, c.nodal);
      EXPECT_FALSE(law->symmetric());
      const std::vector<int> z_components = law->multipliers(dim);
      const int n_z = static_cast<int>(z_components.size());
      // Penetration 1e-4 m: p = 1e6 Pa from the penalty, 1e6 + 1e6 from lambda = -1e6 with the
      // augmented Lagrangian; the stick tests keep the trial well inside mu p, the slip ones far out.
      const double g = -1e-4;
      std::vector<double> z = {-1e6, 0.2e5, -0.1e5};  // LAGS_C, then the tangential tractions
      if (c.normal != ContactEnforcement::AugmentedLagrangian) z.erase(z.begin());
      if (c.normal == ContactEnforcement::Penalty) z.insert(z.begin(), -1e6);  // reported LAGS_C
      z.resize(std::max(n_z, 1));
      PointState start;
      start.status = PointStatus::Stick;
      start.history[0] = 0.5e4, start.history[1] = -0.5e4;
      expect_tangent(*law, at(dim, c, n_z, g, {1e-6, -0.5e-6}, z), start, PointStatus::Stick);
      expect_tangent(*law, at(dim, c, n_z, g, {2e-3, 1e-3}, z), start, PointStatus::Slip);
    }
}

TEST(CoulombLaw, SlipCarriesMuTimesTheNormalForceAlongTheSlipAndOpenCarriesNothing) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.name);
    const auto normal = make_contact_law(c.normal);
    const auto law = make_coulomb_law(*normal, c.friction, c.nodal);
    const int n_z = static_cast<int>(law->multipliers(3).size());
    std::vector<double> z(std::max(n_z, 1), 0.0);
    if (c.normal != ContactEnforcement::Springs) z[0] = -1e6;
    PointState start;
    start.status = PointStatus::Stick;
    const double slip[2] = {3e-3, -4e-3};  // along (0.6, -0.8)
    const PointResponse r = evaluate(*law, at(3, c, n_z, -1e-4, {slip[0], slip[1]}, z), start, true);
    ASSERT_EQ(r.status, PointStatus::Slip);
    const double normal_force = -r.r_q[0];
    ASSERT_GT(normal_force, 0.0);
    // The force conjugate to the slip resists it: along +slip on q, norm mu N.
    EXPECT_NEAR(r.r_q[1], kMu * normal_force * 0.6, 1e-12 * normal_force);
    EXPECT_NEAR(r.r_q[2], -kMu * normal_force * 0.8, 1e-12 * normal_force);
    // Open: no force, and the multipliers' rows hold them at zero.
    const PointResponse open = evaluate(*law, at(3, c, n_z, 1e-4, {slip[0], slip[1]}, z), start, false);
    EXPECT_EQ(open.status, PointStatus::Open);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(open.r_q[k], 0.0);
  }
}

TEST(CoulombLaw, PenaltyKeepsItsTractionAsHistoryAndStartsAtZeroPressureStuck) {
  const auto normal = make_contact_law(ContactEnforcement::Penalty);
  const Case c = kCases[1];
  const auto law = make_coulomb_law(*normal, FrictionEnforcement::Penalty, false);
  EXPECT_EQ(law->n_history(2), 1);
  PointState start;
  start.status = PointStatus::Stick;
  start.history[0] = 1e5;  // Pa; mu p = 3e5 Pa at g = -1e-4
  PointState state;
  state.status = PointStatus::Stick;
  const PointResponse r = law->evaluate(at(2, c, 1, -1e-4, {0.5e-4}, {-1e6}), start, state);
  EXPECT_EQ(r.status, PointStatus::Stick);
  EXPECT_NEAR(state.history[0], 1e5 + 2e9 * 0.5e-4, 1e-6);
  EXPECT_NEAR(r.r_q[1], kWeight * state.history[0], 1e-6);
  // A first contact at zero pressure and no slip: stuck, with its stick stiffness (the block
  // is held tangentially from the first iteration).
  PointState fresh;
  fresh.status = PointStatus::Stick;
  const PointResponse first = law->evaluate(at(2, c, 1, 0.0, {0.0}, {0.0}), PointState{}, fresh);
  EXPECT_EQ(first.status, PointStatus::Stick);
  EXPECT_EQ(first.k_qq[1][1], kWeight * 2e9);
}

TEST(CoulombLaw, MultipliersAreNamedForTheDofMap) {
  const auto al = make_contact_law(ContactEnforcement::AugmentedLagrangian);
  const auto springs = make_contact_law(ContactEnforcement::Springs);
  EXPECT_EQ(make_coulomb_law(*al, FrictionEnforcement::AugmentedLagrangian, false)->multipliers(3),
            (std::vector<int>{LAGS_C, LAGS_F1, LAGS_F2}));
  EXPECT_EQ(make_coulomb_law(*al, FrictionEnforcement::AugmentedLagrangian, false)->multipliers(2),
            (std::vector<int>{LAGS_C, LAGS_F1}));
  EXPECT_TRUE(make_coulomb_law(*springs, FrictionEnforcement::Penalty, true)->multipliers(2).empty());
}

}  // namespace coulomb_law_test
