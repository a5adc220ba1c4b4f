// Non-convergence in StaticSolver: the failure message (instant, loop, residuals,
// converged steps), the steps kept after a failure, and automatic step
// subdivision (DEFI_LIST_INST/ECHEC/DECOUPE) rescuing a step that fails whole.
//
// The problem is one QUAD4 with a single free unknown (node 2, DY) loaded by a
// nodal force F(t) = 1.5 t, plus a saturating spring added through the contact
// hook: r(u) = k u + c atan(u / s) - F. Newton on atan needs 8 iterations for
// the whole step 0 -> 1 (the tangent collapses past the knee), 3 or fewer per
// quarter/sixteenth step; with ITER_GLOB_MAXI = 5 the whole step fails and the
// subdivided one converges to the same root, found here by bisection.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "engine/core/log.hpp"
#include "engine/nonlinear/static_solver.hpp"

namespace lunaster::engine {
namespace {

constexpr double kSpring = 1.0;     // c, N
constexpr double kKnee = 0.01;      // s, m
constexpr double kForce = 1.5;      // F at t = 1, N
constexpr int kFreeNode = 2;

/// The saturating spring c atan(u/s) on one unknown, seen by the solver as a "contact".
class AtanSpring : public ContactHook {
 public:
  explicit AtanSpring(double c) : c_(c) {}
  void add_dofs(DofMap& dofs) override { eq_ = dofs.dof(kFreeNode, DY); }
  void begin_step(const Vector&, const Log&) override {}
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override {
    const double x = u[eq_] / kKnee;
    residual[eq_] += c_ * std::atan(x);
    tangent.emplace_back(eq_, eq_, c_ / kKnee / (1.0 + x * x));
  }
  bool settle(const Vector&, const Log&) override { return true; }
  MatrixKind matrix_kind() const override { return MatrixKind::SymmetricPositiveDefinite; }
  int n_active() const override { return 1; }
  void write_fields(const Vector&, ResultStep&) const override {}

 private:
  double c_;
  int eq_ = -1;
};

struct Problem {
  Mesh mesh;
  FeModel model;
  MechanicalLoads loads;
  Problem() {
    mesh.add_node(0, 0, 0);
    mesh.add_node(1, 0, 0);
    mesh.add_node(1, 1, 0);
    mesh.add_node(0, 1, 0);
    mesh.add_cell(CellType::Quad4, {0, 1, 2, 3});
    mesh.detect_dimension();
    model.mesh = &mesh;
    model.dim = 2;
    model.modelisation = {Modelisation::PlaneStrain};
    model.material = {0};
    model.materials = {{0.01, 0.0, 0.0}};  // soft: the spring dominates
    for (int node : {0, 1, 3})
      for (int cmp : {DX, DY}) loads.dirichlet.push_back({node, cmp, 0.0, 0});
    loads.dirichlet.push_back({kFreeNode, DX, 0.0, 0});
    loads.forces.push_back({kFreeNode, DY, kForce, 0});
    loads.multipliers.push_back([](double t) { return t; });
  }
};

double dy(const ResultStep& step) { return step.nodal.at("DEPL").value(kFreeNode, 1); }

std::string all_text(const Error& e) {
  std::string text = e.message();
  for (const auto& h : e.hints()) text += "\n" + h;
  return text;
}

/// Elastic stiffness of the free unknown, from a linear solve (no spring).
double elastic_stiffness() {
  Problem p;
  std::ostringstream sink;
  Log log(sink, 0);
  StaticSolver solver(p.model, p.loads, NewtonOptions{}, nullptr, log);
  const auto steps = solver.run({0.0, 1.0});
  return kForce / dy(steps.back());
}

/// Root of k u + c atan(u/s) = F by bisection (independent of the solver).
double exact_root(double k, double force) {
  double lo = 0.0, hi = force / k;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (k * mid + kSpring * std::atan(mid / kKnee) < force ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(Subdivision, WholeStepFailsAndKeepsConvergedSteps) {
  Problem p;
  AtanSpring spring(kSpring);
  std::ostringstream sink;
  Log log(sink, 0);
  NewtonOptions options;
  options.iter_glob_maxi = 5;
  StaticSolver solver(p.model, p.loads, options, &spring, log);
  try {
    solver.run({0.0, 0.1, 1.0});
    FAIL() << "the step 0.1 -> 1 should not converge in 5 iterations";
  } catch (const ConvergenceError& e) {
    const std::string text = all_text(e);
    EXPECT_NE(text.find("Newton did not converge at instant 1.000000e+00 within ITER_GLOB_MAXI = 5"), std::string::npos)
        << text;
    EXPECT_NE(text.find("last residuals: RESI_GLOB_RELA = "), std::string::npos) << text;
    EXPECT_NE(text.find("loop: Newton"), std::string::npos) << text;
    EXPECT_NE(text.find("failed in step 2 of 2"), std::string::npos) << text;
    EXPECT_NE(text.find("1 step(s) converged before, the last at instant 1.000000e-01 (NUME_ORDRE 1)"),
              std::string::npos)
        << text;
  }
  // The initial state and the converged first step are kept, with the right values.
  const auto& kept = solver.converged_steps();
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_DOUBLE_EQ(kept[1].inst, 0.1);
  const double k = elastic_stiffness();
  EXPECT_NEAR(dy(kept[1]), exact_root(k, 0.1 * kForce), 1e-6 * exact_root(k, 0.1 * kForce));
}

TEST(Subdivision, DecoupeRescuesTheStep) {
  Problem p;
  AtanSpring spring(kSpring);
  std::ostringstream sink;
  Log log(sink, 1);
  NewtonOptions options;
  options.iter_glob_maxi = 5;
  options.subdivide_levels = 3;
  options.subdivide_parts = 4;
  StaticSolver solver(p.model, p.loads, options, &spring, log);
  const auto steps = solver.run({0.0, 1.0});
  // Sub-steps are stored as steps of their own, ending at the requested instant.
  ASSERT_GT(steps.size(), 2u);
  EXPECT_DOUBLE_EQ(steps.back().inst, 1.0);
  for (size_t i = 1; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].nume_ordre, static_cast<int>(i));
    EXPECT_GT(steps[i].inst, steps[i - 1].inst);
  }
  const double k = elastic_stiffness();
  const double root = exact_root(k, kForce);
  EXPECT_NEAR(dy(steps.back()), root, 1e-6 * root);
  EXPECT_NE(sink.str().find("splitting it into 4 sub-steps (level 1)"), std::string::npos);
  EXPECT_GE(log.n_warnings(), 1);
}

TEST(Subdivision, TooFewLevelsFailsNamingTheLevels) {
  Problem p;
  AtanSpring spring(kSpring);
  std::ostringstream sink;
  Log log(sink, 0);
  NewtonOptions options;
  options.iter_glob_maxi = 5;
  options.subdivide_levels = 1;  // quarter steps: the last one still needs 6 iterations
  options.subdivide_parts = 4;
  StaticSolver solver(p.model, p.loads, options, &spring, log);
  try {
    solver.run({0.0, 1.0});
    FAIL() << "one subdivision level should not be enough";
  } catch (const ConvergenceError& e) {
    const std::string text = all_text(e);
    EXPECT_NE(text.find("still failed after 1 subdivision level(s) (SUBD_NIVEAU)"), std::string::npos) << text;
    EXPECT_NE(text.find("failed in step 1 of 1"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace lunaster::engine
