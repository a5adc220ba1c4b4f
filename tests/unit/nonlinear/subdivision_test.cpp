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
#include "one_quad_spring.hpp"

namespace lunaster::engine {
namespace {

using namespace one_quad;

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
    // The engine speaks of iterations and residuals, with the numbers in failure() for
    // commands/ to name the keywords (commands/failures.cpp).
    EXPECT_NE(text.find("Newton did not converge at instant 1.000000e+00 within 5 iterations"), std::string::npos)
        << text;
    EXPECT_NE(text.find("last residuals: relative "), std::string::npos) << text;
    EXPECT_EQ(text.find("ITER_GLOB_MAXI"), std::string::npos) << text;
    EXPECT_EQ(e.failure().what, Failure::What::NewtonIterations);
    EXPECT_EQ(e.failure().limit, 5);
    EXPECT_TRUE(e.failure().residuals_known);
    EXPECT_GT(e.failure().relative, 1e-6);
    EXPECT_NE(text.find("loop: Newton"), std::string::npos) << text;
    EXPECT_NE(text.find("failed in step 2 of 2"), std::string::npos) << text;
    EXPECT_NE(text.find("1 step(s) converged before, the last at instant 1.000000e-01 (stored step 1)"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.find("NUME_ORDRE"), std::string::npos) << text;
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
    EXPECT_NE(text.find("still failed after 1 subdivision level(s)"), std::string::npos) << text;
    EXPECT_EQ(text.find("SUBD_NIVEAU"), std::string::npos) << text;
    EXPECT_EQ(e.failure().subdivision_levels, 1);
    EXPECT_NE(text.find("failed in step 1 of 1"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace lunaster::engine
