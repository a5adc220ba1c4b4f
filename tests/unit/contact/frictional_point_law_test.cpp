// A frictional law added through the point-law interface alone (point_law.hpp), without
// touching the engine: a regularised Coulomb law defined here, evaluated at points. Its
// residual and tangent blocks match central finite differences, its statuses come out open,
// stick and slip on chosen inputs, its multipliers find their unknowns in the DOF map by name,
// and a snapshot of the points' states restores every status and every history variable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/contact/point_law.hpp"
#include "point_law_unknowns.hpp"

namespace {

using namespace lunaster::engine;
using namespace lunaster::engine::contact;

// Normal condition: the augmented Lagrangian of the engine's CONTINUE law (lambda = LAGS_C,
// negative in compression; closed iff lambda + rho g < 0; pressure p = -(lambda + rho g)).
// Tangential: Coulomb regularised by a stick stiffness eps_t (Pa/m): the trial traction is
// the traction at the step's start plus eps_t times the slip increment since then; within
// mu p it sticks, beyond it slips with |t| = mu p along the trial. History: the tangential
// traction (n_tangents values). The tangent in slip couples the tangential force to the
// pressure but not the reverse: unsymmetric.
class RegularisedCoulomb final : public PointLaw {
 public:
  RegularisedCoulomb(double mu, double eps_t) : mu_(mu), eps_t_(eps_t) {}
  const char* name() const override { return "regularised Coulomb (test)"; }
  std::vector<int> multipliers(int /*dim*/) const override { return {LAGS_C}; }
  int n_tangents(int dim) const override { return dim - 1; }
  int n_history(int dim) const override { return dim - 1; }
  bool symmetric() const override { return false; }

  PointResponse evaluate(const PointKinematics& in, const PointState& start, PointState& state) const override {
    const int nt = in.n_tangents;
    const double w = in.weight, rho = in.coefficient, lambda = in.z[0], g = in.q[0];
    PointResponse r;
    r.n_q = 1 + nt;
    r.n_z = 1;
    const double s = lambda + rho * g;
    if (s >= 0.0) {  // open: no force, the multiplier's own row holds it at zero
      r.r_z[0] = -w / rho * lambda;
      r.k_zz[0][0] = -w / rho;
      r.status = PointStatus::Open;
      state.status = r.status;
      for (int k = 0; k < nt; ++k) state.history[k] = 0.0;
      return r;
    }
    r.r_q[0] = w * s;
    r.k_qq[0][0] = w * rho;
    r.k_qz[0][0] = w;
    r.r_z[0] = w * g;
    r.k_zq[0][0] = w;
    const double p = -s;
    double trial[2] = {}, norm2 = 0.0;
    for (int k = 0; k < nt; ++k) {
      trial[k] = start.history[k] + eps_t_ * in.dq_step[1 + k];
      norm2 += trial[k] * trial[k];
    }
    const double norm = std::sqrt(norm2);
    if (norm <= mu_ * p) {
      r.status = PointStatus::Stick;
      for (int k = 0; k < nt; ++k) {
        r.r_q[1 + k] = w * trial[k];
        r.k_qq[1 + k][1 + k] = w * eps_t_;
        state.history[k] = trial[k];
      }
    } else {
      r.status = PointStatus::Slip;
      for (int k = 0; k < nt; ++k) {
        const double n_k = trial[k] / norm, t_k = mu_ * p * n_k;
        r.r_q[1 + k] = w * t_k;
        state.history[k] = t_k;
        // dp/dg = -rho, dp/dlambda = -1.
        r.k_qq[1 + k][0] = -w * mu_ * rho * n_k;
        r.k_qz[1 + k][0] = -w * mu_ * n_k;
        for (int l = 0; l < nt; ++l)
          r.k_qq[1 + k][1 + l] = w * mu_ * p * eps_t_ / norm * ((k == l ? 1.0 : 0.0) - n_k * trial[l] / norm);
      }
    }
    state.status = r.status;
    return r;
  }

 private:
  double mu_, eps_t_;
};

constexpr double kMu = 0.3, kEpsT = 2e9, kRho = 1e10, kWeight = 0.25;

PointKinematics kinematics(int dim, double g, double lambda, const std::vector<double>& slip,
                           const std::vector<double>& slip_at_start) {
  PointKinematics in;
  in.n_tangents = dim - 1;
  in.q[0] = g;
  for (int k = 0; k < dim - 1; ++k) {
    in.q[1 + k] = slip[k];
    in.dq_step[1 + k] = slip[k] - slip_at_start[k];
  }
  in.z[0] = lambda;
  in.weight = kWeight;
  in.coefficient = kRho;
  return in;
}

using point_law_unknowns::perturb;
using point_law_unknowns::residual;
using point_law_unknowns::tangent;

// The blocks against central differences of the residual, at a point well inside its status
// (the steps, 1e-7 of each unknown's scale, never cross a status boundary there).
void expect_tangent_matches_differences(const PointLaw& law, const PointKinematics& at, const PointState& start,
                                        PointStatus expected) {
  PointState state;
  const PointResponse r = law.evaluate(at, start, state);
  ASSERT_EQ(r.status, expected);
  const int n_q = r.n_q, n = r.n_q + r.n_z;
  bool any = false;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) any = any || tangent(r, n_q, i, j) != 0.0;
  ASSERT_TRUE(any);
  for (int j = 0; j < n; ++j) {
    const double h = 1e-7 * (j < n_q ? 1e-3 : 1e6);  // gaps ~ 1e-3 m, multipliers ~ 1e6 Pa
    PointKinematics plus = at, minus = at;
    perturb(plus, n_q, j, h);
    perturb(minus, n_q, j, -h);
    PointState sp, sm;
    const PointResponse rp = law.evaluate(plus, start, sp), rm = law.evaluate(minus, start, sm);
    ASSERT_EQ(rp.status, expected);
    ASSERT_EQ(rm.status, expected);
    // Relative to the column's largest entry (a column is one unknown's units).
    double column = 0.0;
    for (int i = 0; i < n; ++i) column = std::max(column, std::abs(tangent(r, n_q, i, j)));
    for (int i = 0; i < n; ++i) {
      const double fd = (residual(rp, n_q, i) - residual(rm, n_q, i)) / (2.0 * h);
      EXPECT_NEAR(tangent(r, n_q, i, j), fd, 1e-6 * column) << "row " << i << ", column " << j;
    }
  }
}

TEST(FrictionalPointLaw, BlocksMatchFiniteDifferencesInStickAndSlip2DAnd3D) {
  const RegularisedCoulomb law(kMu, kEpsT);
  EXPECT_FALSE(law.symmetric());
  for (int dim : {2, 3}) {
    SCOPED_TRACE("dim " + std::to_string(dim));
    PointState start;
    start.status = PointStatus::Stick;
    start.history[0] = 1e5, start.history[1] = -2e5;  // traction at the step's start (Pa)
    // p = -(lambda + rho g) = 1e6 + 1e7 * 1e-3 ... g = -1e-4: p = 2e6 Pa, mu p = 6e5 Pa.
    const double g = -1e-4, lambda = -1e6;
    // Stick: trial = start + 2e9 * 1e-4 = 1e5 + 2e5 (and -2e5 - 1e5): |trial| < 6e5.
    expect_tangent_matches_differences(law, kinematics(dim, g, lambda, {1.1e-3, 0.95e-3}, {1.0e-3, 1.0e-3}), start,
                                       PointStatus::Stick);
    // Slip: an increment of 1e-3 gives |trial| ~ 2e6 > mu p.
    expect_tangent_matches_differences(law, kinematics(dim, g, lambda, {2.0e-3, 0.2e-3}, {1.0e-3, 1.0e-3}), start,
                                       PointStatus::Slip);
    // Open: only the multiplier's row.
    expect_tangent_matches_differences(law, kinematics(dim, 1e-3, -1e6, {2.0e-3, 0.2e-3}, {1.0e-3, 1.0e-3}), start,
                                       PointStatus::Open);
  }
}

TEST(FrictionalPointLaw, StatusesOpenStickSlipAndTheCoulombBound) {
  const RegularisedCoulomb law(kMu, kEpsT);
  PointState start;  // stuck at zero traction
  start.status = PointStatus::Stick;
  const double g = -1e-4, lambda = -1e6, p = -(lambda + kRho * g), bound = kMu * p;
  PointState state;
  // Opened by a gap larger than the multiplier's reach: no force, the history cleared.
  state.history[0] = 7.0;
  PointResponse r = law.evaluate(kinematics(2, 2e-4, lambda, {0.0}, {0.0}), start, state);
  EXPECT_EQ(r.status, PointStatus::Open);
  EXPECT_EQ(state.status, PointStatus::Open);
  EXPECT_EQ(r.r_q[0], 0.0);
  EXPECT_EQ(state.history[0], 0.0);
  // An increment just below the stick limit: sticks, the traction eps_t times the increment.
  const double limit = bound / kEpsT;
  r = law.evaluate(kinematics(2, g, lambda, {0.99 * limit}, {0.0}), start, state);
  EXPECT_EQ(r.status, PointStatus::Stick);
  EXPECT_NEAR(state.history[0], 0.99 * bound, 1e-9 * bound);
  EXPECT_NEAR(r.r_q[1], kWeight * 0.99 * bound, 1e-9 * bound);
  // Just above: slips, the traction exactly mu p whatever the increment, against its sign.
  for (double factor : {1.01, 10.0, -3.0}) {
    r = law.evaluate(kinematics(2, g, lambda, {factor * limit}, {0.0}), start, state);
    EXPECT_EQ(r.status, PointStatus::Slip) << factor;
    EXPECT_NEAR(state.history[0], std::copysign(bound, factor), 1e-12 * bound) << factor;
  }
  // 3D: the slip direction is the trial's.
  r = law.evaluate(kinematics(3, g, lambda, {3 * limit, 4 * limit}, {0.0, 0.0}), start, state);
  EXPECT_EQ(r.status, PointStatus::Slip);
  EXPECT_NEAR(state.history[0], 0.6 * bound, 1e-12 * bound);
  EXPECT_NEAR(state.history[1], 0.8 * bound, 1e-12 * bound);
}

// The law's multipliers are DOF-map components; the map finds a node's by name and lists the
// components a displacement result reports, friction's included.
TEST(FrictionalPointLaw, MultipliersByNameInTheDofMap) {
  DofMap dofs;
  dofs.add_nodes(4);
  for (int node = 0; node < 4; ++node)
    for (int k = 0; k < 2; ++k) dofs.add(node, k);
  const std::vector<int> frictional = {LAGS_C, LAGS_F1};
  for (int node : {1, 2})
    for (int c : frictional) dofs.add(node, c);
  EXPECT_EQ(dofs.dof_named(1, "LAGS_F1"), dofs.dof(1, LAGS_F1));
  EXPECT_GE(dofs.dof_named(2, "LAGS_C"), 8);
  EXPECT_EQ(dofs.dof_named(0, "LAGS_C"), -1);
  EXPECT_EQ(dofs.dof_named(1, "LAGS_F2"), -1);
  EXPECT_EQ(dofs.dof_named(1, "NOPE"), -1);
  EXPECT_EQ(dofs.component_of(dofs.dof_named(2, "LAGS_F1")), LAGS_F1);
  EXPECT_EQ(dofs.result_component_names(), (std::vector<std::string>{"DX", "DY", "LAGS_C", "LAGS_F1"}));
  EXPECT_EQ(component_of_name("LAGS_F2"), LAGS_F2);
  EXPECT_EQ(component_of_name("LAGS_F3"), -1);
  dofs.add(3, LAGR_DX);  // a relation's multiplier: in the map, not in a displacement result
  EXPECT_EQ(dofs.components().back(), LAGR_DX);
  EXPECT_EQ(dofs.result_components().size(), 4u);
}

// Three points through two steps: a snapshot at the first step's end restores, after a
// diverged attempt of the second changed them, every status and every history variable, and
// the next evaluation from the restored states repeats the first attempt's numbers.
TEST(FrictionalPointLaw, SnapshotRestoresStatusesAndHistory) {
  const RegularisedCoulomb law(kMu, kEpsT);
  PointStates states;
  states.resize(3);
  const double g = -1e-4, lambda = -1e6, limit = kMu * 2e6 / kEpsT;
  // Step 1: point 0 open, point 1 sticks, point 2 slips.
  const std::vector<PointKinematics> step1 = {kinematics(3, 1e-3, 0.0, {0.0, 0.0}, {0.0, 0.0}),
                                              kinematics(3, g, lambda, {0.5 * limit, 0.0}, {0.0, 0.0}),
                                              kinematics(3, g, lambda, {0.0, 2.0 * limit}, {0.0, 0.0})};
  for (size_t i = 0; i < 3; ++i) law.evaluate(step1[i], states.start(i), states.present(i));
  states.commit();
  EXPECT_EQ(states.count(PointStatus::Open), 1);
  EXPECT_EQ(states.count(PointStatus::Stick), 1);
  EXPECT_EQ(states.count(PointStatus::Slip), 1);
  const PointStates::Snapshot saved = states.snapshot();
  // Step 2, first attempt: all three slip the other way, histories change.
  auto second = [&](size_t i) {
    return kinematics(3, g, lambda, {-3.0 * limit, 1.0 * limit}, {step1[i].q[1], step1[i].q[2]});
  };
  std::vector<PointResponse> first_attempt;
  for (size_t i = 0; i < 3; ++i) first_attempt.push_back(law.evaluate(second(i), states.start(i), states.present(i)));
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(states.present(i).status, PointStatus::Slip);
  states.commit();  // as if the attempt had converged, then was undone by a subdivision
  EXPECT_NE(states.start(1), saved.start[1]);
  states.restore(saved);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(states.start(i), saved.start[i]) << i;
    EXPECT_EQ(states.present(i), saved.present[i]) << i;
  }
  EXPECT_EQ(states.start(1).status, PointStatus::Stick);
  EXPECT_EQ(states.start(2).status, PointStatus::Slip);
  EXPECT_NEAR(states.start(1).history[0], 0.5 * kMu * 2e6, 1e-6);
  EXPECT_NEAR(states.start(2).history[1], kMu * 2e6, 1e-6);
  for (size_t i = 0; i < 3; ++i) {
    const PointResponse again = law.evaluate(second(i), states.start(i), states.present(i));
    for (int k = 0; k < again.n_q; ++k) EXPECT_EQ(again.r_q[k], first_attempt[i].r_q[k]) << i << " " << k;
  }
}

}  // namespace
