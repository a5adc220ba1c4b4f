// A nonlinear behaviour solved by the production Newton driver (StaticSolver): the toy hardening
// bar of tests/unit/fe/toy_plasticity_test.cpp (its law in hardening_bar.hpp) given to the
// driver through set_behaviours, with nothing else changed.
//
// The problem: the unit square (distorted interior nodes, QUAD4, plane strain), u_x = 0 on x = 0,
// u_y = 0 at the origin, nodal forces of a uniform traction t(instant) along x on x = 1. The
// exact solution is uniform (hardening_bar.hpp): u_x(1, y) = t / E + p(t), EPSPEQ = p(t),
// SIXX = t, which bilinear cells and the exact nodal forces of a uniform traction hold exactly.
// Newton on it is Newton on sigma(eps_xx) = t, whose relative residuals go as
// r_{k+1} ~ C r_k^2 with C = t |sigma''| / (2 sigma'^2) at the solution (rate_constant).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/log.hpp"
#include "engine/material/cell_behaviours.hpp"
#include "engine/nonlinear/static_solver.hpp"
#include "tests/unit/fe/fe_test_util.hpp"
#include "tests/unit/fe/hardening_bar.hpp"
#include "tests/unit/fe/med_elga.hpp"

namespace lunaster::engine {
namespace {

using namespace hardening_bar;

constexpr int kCells = 4;

/// The hardening bar's law whose integration fails when the xx strain moves by more than
/// `max_increment` in one step (a local integrator that needs small increments): a whole step
/// fails, its sub-steps do not.
class ShortStepBar final : public Behaviour {
 public:
  explicit ShortStepBar(double max_increment) : max_increment_(max_increment) {}
  bool is_linear() const override { return false; }
  const std::vector<std::string>& variable_names() const override { return law_.variable_names(); }
  IntegrationStatus integrate(const PointInput& in, PointOutput& out) const override {
    if (std::abs(in.strain_end(0) - in.strain_start(0)) > max_increment_) return IntegrationStatus::Failed;
    return law_.integrate(in, out);
  }

 private:
  HardeningBar law_;
  double max_increment_;
};

/// The hardening bar's law counting its integrations: with the tangent asked, and without.
class CountingBar final : public Behaviour {
 public:
  bool is_linear() const override { return false; }
  const std::vector<std::string>& variable_names() const override { return law_.variable_names(); }
  IntegrationStatus integrate(const PointInput& in, PointOutput& out) const override {
    ++(out.want_tangent ? with_tangent : without_tangent);
    return law_.integrate(in, out);
  }
  mutable std::atomic<long> with_tangent{0}, without_tangent{0};

 private:
  HardeningBar law_;
};

/// The bar, its loads (traction = the multiplier `traction` of the instant) and its behaviours.
struct DrivenBar {
  test::BlockBuilder block{CellType::Quad4, kCells, 0.3};
  FeModel model;
  MechanicalLoads loads;
  std::unique_ptr<CellBehaviours> behaviours;
  DrivenBar(std::function<double(double)> traction, std::shared_ptr<const Behaviour> law) {
    block.fill();
    model = test::make_model(block.mesh(), 2, Modelisation::PlaneStrain, ElasticMaterial{kE, 0.0, 0.0});
    behaviours = std::make_unique<CellBehaviours>(model);
    behaviours->assign(model.volume_cells(), std::move(law));
    for (int j = 0; j <= kCells; ++j) loads.dirichlet.push_back({block.vertex(0, j), DX, 0.0, 0});
    loads.dirichlet.push_back({block.vertex(0, 0), DY, 0.0, 0});
    for (int j = 0; j < kCells; ++j)
      for (int end : {j, j + 1}) loads.forces.push_back({block.vertex(kCells, end), DX, 0.5 / kCells, 0});
    loads.multipliers.push_back(std::move(traction));
  }
};

/// What a run gave: its steps (or those converged before a failure), its log, its error.
struct Outcome {
  std::vector<ResultStep> steps;
  std::string log;
  bool failed = false;
  std::string error;
};

Outcome solve(DrivenBar& bar, const std::vector<double>& instants, NewtonOptions options) {
  std::ostringstream sink;
  Log log(sink, 1);
  StaticSolver solver(bar.model, bar.loads, options, nullptr, log);
  solver.set_behaviours(bar.behaviours.get());
  Outcome out;
  try {
    out.steps = solver.run(instants);
  } catch (const ConvergenceError& e) {
    out.failed = true;
    out.error = e.what();
    out.steps = solver.converged_steps();
  }
  out.log = sink.str();
  return out;
}

NewtonOptions tight() {
  NewtonOptions options;
  options.resi_glob_rela = 1e-12;  // Newton to round-off: the exact solution to 1e-10
  options.iter_glob_maxi = 20;
  return options;
}

/// The relative residuals of each instant's Newton iterations, as the driver's log prints them
/// ("instant T" then "  | iter |  relative |  absolute |" rows), instants in log order.
std::vector<std::pair<double, std::vector<double>>> logged_residuals(const std::string& log) {
  std::vector<std::pair<double, std::vector<double>>> out;
  std::istringstream lines(log);
  std::string line;
  while (std::getline(lines, line)) {
    double t = 0.0, relative = 0.0, absolute = 0.0;
    int iter = 0;
    if (std::sscanf(line.c_str(), "instant %lf", &t) == 1) out.push_back({t, {}});
    else if (!out.empty() && std::sscanf(line.c_str(), " | %d | %lf | %lf |", &iter, &relative, &absolute) == 3) {
      EXPECT_EQ(iter, static_cast<int>(out.back().second.size())) << line;
      out.back().second.push_back(relative);
    }
  }
  return out;
}

/// u_x at x = 1, EPSPEQ and SIXX at every point: the exact uniform solution at traction t.
void expect_exact(const DrivenBar& bar, const ResultStep& step, double t) {
  const double p = exact_p(t), exx = t / kE + p;
  for (int j = 0; j <= kCells; ++j) {
    test::expect_close(step.nodal.at("DEPL").value(bar.block.vertex(kCells, j), 0), exx, 1e-10, 0.0, "u_x at x = 1");
    test::expect_close(step.nodal.at("DEPL").value(bar.block.vertex(kCells, j), 1), 0.0, 0.0, 1e-12 * exx,
                       "u_y at x = 1");
  }
  const ElgaField& vari = step.elga.at("VARI_ELGA");
  const ElgaField& sief = step.elga.at("SIEF_ELGA");
  ASSERT_EQ(vari.components, (std::vector<std::string>{"V1", "V2"}));
  ASSERT_EQ(sief.components, (std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY"}));
  const int n_points = vari.cell_offsets.back();
  ASSERT_EQ(n_points, 4 * kCells * kCells);
  for (int r = 0; r < n_points; ++r) {
    test::expect_close(vari.values[2 * r], p, 1e-10, 1e-14, "EPSPEQ");
    test::expect_close(sief.values[4 * r], t, 1e-10, 0.0, "SIXX");
  }
}

TEST(BehaviourDriver, NewtonConvergesAtTheLawsRateToTheExactSolution) {
  const std::map<double, double> traction{{0.0, 0.0}, {1.0, 150.0}, {2.0, 250.0}, {3.0, 290.0}};
  DrivenBar bar([&](double t) { return traction.at(t); }, std::make_shared<HardeningBar>());
  const Outcome r = solve(bar, {0.0, 1.0, 2.0, 3.0}, tight());
  ASSERT_FALSE(r.failed) << r.error << "\n" << r.log;
  ASSERT_EQ(r.steps.size(), 4u);
  const auto residuals = logged_residuals(r.log);
  ASSERT_EQ(residuals.size(), 3u) << r.log;
  for (int i = 1; i <= 3; ++i) {
    const double t = traction.at(r.steps[i].inst);
    SCOPED_TRACE("t = " + std::to_string(t));
    expect_exact(bar, r.steps[i], t);
    const std::vector<double>& res = residuals[i - 1].second;
    if (t < kSy) {  // elastic: the first solve is exact
      EXPECT_LE(res.size(), 2u) << r.log;
      continue;
    }
    // Every iteration whose residual is above round-off and whose previous one is near enough
    // for the asymptote (below 1e-2) is held to 2 C, and the last one's ratio is C to 5 %: the
    // rate is the law's (a linear rate would give ratios ~ 1 / r_k, over 1e2 here).
    const double c = rate_constant(t);
    ASSERT_GE(res.size(), 4u) << "too few iterations to see a rate\n" << r.log;
    double last = 0.0;
    int rated = 0;
    for (size_t k = 1; k + 1 < res.size(); ++k) {
      if (res[k] < 1e-11 || res[k - 1] > 1e-2) continue;
      const double ratio = res[k] / (res[k - 1] * res[k - 1]);
      std::printf("  t = %g, iteration %zu: r_k / r_{k-1}^2 = %.4g (C = %.4g)\n", t, k, ratio, c);
      EXPECT_LE(ratio, 2.0 * c) << "iteration " << k;
      last = ratio;
      ++rated;
    }
    EXPECT_GE(rated, 1);
    EXPECT_NEAR(last, c, 0.05 * c) << "the asymptotic rate";
  }
}

TEST(BehaviourDriver, EachNewtonIterationIntegratesEachPointOnce) {
  // The residual and the tangent of an iteration come from one integration of each point (its
  // stress and its tangent together): the tangent at rest once, then one integration per
  // Newton iteration logged (those that solve and the one that converges), all with the tangent.
  const std::map<double, double> traction{{0.0, 0.0}, {1.0, 150.0}, {2.0, 250.0}, {3.0, 290.0}};
  auto law = std::make_shared<CountingBar>();
  DrivenBar bar([&](double t) { return traction.at(t); }, law);
  const Outcome r = solve(bar, {0.0, 1.0, 2.0, 3.0}, tight());
  ASSERT_FALSE(r.failed) << r.error << "\n" << r.log;
  long iterations = 0;
  for (const auto& instant : logged_residuals(r.log)) iterations += static_cast<long>(instant.second.size());
  ASSERT_GE(iterations, 8) << r.log;  // the plastic steps iterate
  const long points = 4 * kCells * kCells;
  EXPECT_EQ(law->with_tangent.load(), points * (1 + iterations));
  EXPECT_EQ(law->without_tangent.load(), 0);
  expect_exact(bar, r.steps.back(), 290.0);
}

TEST(BehaviourDriver, AStepWithoutEquilibriumIsSubdividedFromTheRestoredStates) {
  // Instants 0, 1, 2 with tractions 0, 250, 320 (the hardening saturates at sy + Q = 300: the
  // step to 320 has no equilibrium) and 290 at instant 1.5. Run A: 1 then 1.5. Run B: 1, then
  // the step to 2 fails, is split in two, and its first half (to 1.5, 290) converges from the
  // states restored to the step's start: the same iterations, displacements and fields as A's,
  // bit for bit; its second half fails again and the run ends with the failure.
  const auto traction = [](double t) { return t <= 1.0 ? 250.0 * t : 250.0 + 80.0 * (t - 1.0); };
  ASSERT_EQ(traction(1.5), 290.0);
  DrivenBar bar(traction, std::make_shared<HardeningBar>());
  const Outcome a = solve(bar, {0.0, 1.0, 1.5}, tight());
  ASSERT_FALSE(a.failed) << a.error;
  NewtonOptions split = tight();
  split.subdivide_levels = 1;
  split.subdivide_parts = 2;
  const Outcome b = solve(bar, {0.0, 1.0, 2.0}, split);
  ASSERT_TRUE(b.failed) << b.log;
  EXPECT_NE(b.log.find("step to instant 2.000000e+00 failed"), std::string::npos) << b.log;
  EXPECT_NE(b.error.find("still failed after 1 subdivision level(s)"), std::string::npos) << b.error;
  ASSERT_EQ(b.steps.size(), 3u);
  EXPECT_EQ(b.steps[2].inst, 1.5);
  expect_exact(bar, b.steps[2], 290.0);
  const auto res_a = logged_residuals(a.log), res_b = logged_residuals(b.log);
  ASSERT_EQ(res_a.size(), 2u);
  ASSERT_GE(res_b.size(), 3u);
  EXPECT_EQ(res_b[2].first, 1.5);
  EXPECT_EQ(res_a[1].second, res_b[2].second) << "the iterations to 290";
  for (const char* f : {"DEPL"}) EXPECT_EQ(a.steps[2].nodal.at(f).values, b.steps[2].nodal.at(f).values) << f;
  for (const char* f : {"SIEF_ELGA", "VARI_ELGA"})
    EXPECT_EQ(a.steps[2].elga.at(f).values, b.steps[2].elga.at(f).values) << f;
}

TEST(BehaviourDriver, AFailedIntegrationSubdividesTheStep) {
  // Tractions 250 at instant 1, 290 at instant 2; the law refuses xx strain increments above
  // half of the step 1 -> 2's: that step fails in its Newton iterations (its iterates climb to
  // the solution from below), its four sub-steps (the largest the last, about 43 % of it)
  // converge, to the exact solution.
  const auto traction = [](double t) { return t <= 1.0 ? 250.0 * t : 250.0 + 40.0 * (t - 1.0); };
  const double step = 40.0 / kE + exact_p(290.0) - exact_p(250.0);
  DrivenBar bar(traction, std::make_shared<ShortStepBar>(0.5 * step));
  const Outcome whole_step = solve(bar, {0.0, 1.0, 2.0}, tight());
  ASSERT_TRUE(whole_step.failed);
  EXPECT_NE(whole_step.error.find("a behaviour's integration failed at an integration point at instant 2.000000e+00"),
            std::string::npos)
      << whole_step.error;
  EXPECT_EQ(whole_step.steps.size(), 2u);
  NewtonOptions split = tight();
  split.subdivide_levels = 1;
  split.subdivide_parts = 4;
  const Outcome r = solve(bar, {0.0, 1.0, 2.0}, split);
  ASSERT_FALSE(r.failed) << r.error << "\n" << r.log;
  EXPECT_NE(r.log.find("step to instant 2.000000e+00 failed (a behaviour's integration failed"), std::string::npos);
  ASSERT_EQ(r.steps.size(), 6u);  // the initial state, instant 1, four sub-steps
  for (size_t i = 1; i < r.steps.size(); ++i) {
    SCOPED_TRACE("instant " + std::to_string(r.steps[i].inst));
    expect_exact(bar, r.steps[i], traction(r.steps[i].inst));
  }
}

TEST(BehaviourDriver, EachStoredInstantsStatesReachTheResultFile) {
  // The driver's steps as the result writer takes them (IMPR_RESU's path): SIEF_ELGA and
  // VARI_ELGA of every stored instant in the MED file, read back with the MED library.
  const std::map<double, double> traction{{0.0, 0.0}, {1.0, 150.0}, {2.0, 250.0}, {3.0, 290.0}};
  DrivenBar bar([&](double t) { return traction.at(t); }, std::make_shared<HardeningBar>());
  std::vector<ResultStep> steps = solve(bar, {0.0, 1.0, 2.0, 3.0}, tight()).steps;
  ASSERT_EQ(steps.size(), 4u);
  const std::string path = test::write_bar_result(bar.block.mesh(), steps, "behaviour_driver");
  for (const ResultStep& step : steps) {
    const double t = traction.at(step.inst);
    SCOPED_TRACE("t = " + std::to_string(t));
    const test::Quad4Elga vari = test::read_quad4_elga(path, "RESU____VARI_ELGA", step.nume_ordre, 2);
    const test::Quad4Elga sief = test::read_quad4_elga(path, "RESU____SIEF_ELGA", step.nume_ordre, 4);
    ASSERT_EQ(vari.n_cells, kCells * kCells);
    ASSERT_EQ(sief.n_cells, kCells * kCells);
    ASSERT_EQ(vari.n_points, 4);
    EXPECT_EQ(vari.localization, "QUAD4_4_POINTS");
    for (int r = 0; r < vari.n_cells * vari.n_points; ++r) {
      test::expect_close(vari.values[2 * r], exact_p(t), 1e-10, 1e-14, "EPSPEQ");
      test::expect_close(sief.values[4 * r], t, 1e-10, 1e-12, "SIXX");
    }
  }
}

TEST(BehaviourDriver, LinearBehavioursKeepTheElasticPath) {
  // Every behaviour linear (the model's elasticity): the run is the elastic one, bit for bit,
  // with no point fields.
  const auto traction = [](double t) { return 150.0 * t; };
  DrivenBar plain(traction, std::make_shared<HardeningBar>());
  CellBehaviours elastic(plain.model);
  std::ostringstream sink_a, sink_b;
  Log log_a(sink_a, 1), log_b(sink_b, 1);
  StaticSolver without(plain.model, plain.loads, NewtonOptions{}, nullptr, log_a);
  StaticSolver with(plain.model, plain.loads, NewtonOptions{}, nullptr, log_b);
  with.set_behaviours(&elastic);
  const auto steps_a = without.run({0.0, 1.0}), steps_b = with.run({0.0, 1.0});
  EXPECT_EQ(steps_a.back().nodal.at("DEPL").values, steps_b.back().nodal.at("DEPL").values);
  EXPECT_TRUE(steps_b.back().elga.empty());
  EXPECT_EQ(sink_a.str(), sink_b.str());
}

}  // namespace
}  // namespace lunaster::engine
