// The Newton driver's matrix policy (STAT_NON_LINE NEWTON: REAC_ITER, MATRICE): how often
// StaticSolver factorises, proven on the production driver by the factorisations it counts
// and logs, with the converged answer unchanged.
//
// Problem: one_quad_spring.hpp (k u + c atan(u / s) = F t on one unknown), F = 0.5 N so the
// root stays near the knee of the spring (tangent at the root about 0.8 of the initial one):
// full Newton needs a few iterations per instant, a modified Newton (old factors, current
// residual) converges linearly to the same root.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/log.hpp"
#include "engine/nonlinear/static_solver.hpp"
#include "one_quad_spring.hpp"

namespace lunaster::engine {
namespace {

using namespace one_quad;

constexpr double kPolicyForce = 0.5;  // N at t = 1
const std::vector<double> kInstants = {0.0, 0.5, 1.0};

struct PolicyRun {
  std::vector<ResultStep> steps;
  SolverStats stats;
  std::string log;
};

/// Solves the spring problem with the given matrix policy, converging tightly so that
/// full and modified Newton can be compared far below the deck tolerances.
PolicyRun run_spring(int reac_iter) {
  Problem p(kPolicyForce);
  AtanSpring spring(kSpring);
  std::ostringstream sink;
  Log log(sink, 1);
  NewtonOptions options;
  options.reac_iter = reac_iter;
  options.resi_glob_rela = 1e-12;
  options.iter_glob_maxi = 80;
  StaticSolver solver(p.model, p.loads, options, &spring, log);
  PolicyRun run;
  run.steps = solver.run(kInstants);
  run.stats = solver.stats();
  run.log = sink.str();
  return run;
}

/// (Newton iterations, factorisations) of each instant, from the solver's log lines.
std::vector<std::pair<int, int>> per_instant(const std::string& log) {
  std::vector<std::pair<int, int>> out;
  const std::regex line("converged in ([0-9]+) Newton iteration\\(s\\), ([0-9]+) factorisation\\(s\\)");
  for (std::sregex_iterator it(log.begin(), log.end(), line), end; it != end; ++it)
    out.emplace_back(std::stoi((*it)[1]), std::stoi((*it)[2]));
  return out;
}

TEST(MatrixPolicy, ReacIterOneFactorisesAtEveryIteration) {
  const PolicyRun full = run_spring(1);
  EXPECT_EQ(full.stats.factorisations, full.stats.newton_iterations);
  EXPECT_GT(full.stats.newton_iterations, 2 * 2) << "the problem should need several iterations per instant";
  EXPECT_EQ(full.log.find("reused"), std::string::npos);
  const double k = elastic_stiffness();
  for (size_t i = 1; i < kInstants.size(); ++i) {
    const double root = exact_root(k, kPolicyForce * kInstants[i]);
    EXPECT_NEAR(dy(full.steps[i]), root, 1e-10 * root);
  }
}

TEST(MatrixPolicy, ReacIterZeroFactorisesOncePerInstantAndReachesTheSameRoot) {
  const PolicyRun full = run_spring(1);
  const PolicyRun modified = run_spring(0);
  // One factorisation per instant (its first iteration), reused by every other iteration:
  // fewer factorisations, more iterations, the same converged answer.
  EXPECT_EQ(modified.stats.factorisations, 2);
  EXPECT_GT(modified.stats.newton_iterations, full.stats.newton_iterations);
  EXPECT_NE(modified.log.find("(factorisation of iteration 0 reused)"), std::string::npos);
  for (size_t i = 1; i < kInstants.size(); ++i)
    EXPECT_NEAR(dy(modified.steps[i]), dy(full.steps[i]), 1e-9 * std::abs(dy(full.steps[i])));
}

TEST(MatrixPolicy, ReacIterTwoFactorisesEverySecondIteration) {
  const PolicyRun every_second = run_spring(2);
  const auto counts = per_instant(every_second.log);
  ASSERT_EQ(counts.size(), 2u);
  for (const auto& [iterations, factorisations] : counts) {
    EXPECT_GT(iterations, 2);
    EXPECT_EQ(factorisations, (iterations + 1) / 2) << iterations << " iterations";  // iterations 0, 2, 4, ...
  }
  const PolicyRun full = run_spring(1);
  EXPECT_LT(every_second.stats.factorisations, full.stats.factorisations);
  for (size_t i = 1; i < kInstants.size(); ++i)
    EXPECT_NEAR(dy(every_second.steps[i]), dy(full.steps[i]), 1e-9 * std::abs(dy(full.steps[i])));
}

/// A linear problem (no spring) over several instants, with the tangent or the elastic matrix.
PolicyRun run_linear(bool elastic) {
  Problem p(kPolicyForce);
  std::ostringstream sink;
  Log log(sink, 1);
  NewtonOptions options;
  options.elastic_matrix = elastic;
  StaticSolver solver(p.model, p.loads, options, nullptr, log);
  PolicyRun run;
  run.steps = solver.run({0.0, 0.25, 0.5, 0.75, 1.0});
  run.stats = solver.stats();
  run.log = sink.str();
  return run;
}

TEST(MatrixPolicy, ElasticMatrixIsFactorisedOnceForTheWholeRun) {
  const PolicyRun tangent = run_linear(false);
  const PolicyRun elastic = run_linear(true);
  // Linear elasticity: the tangent is the elastic matrix, the same at every instant, so the
  // first instant's factors serve the next three either way.
  EXPECT_EQ(tangent.stats.factorisations, 1);
  EXPECT_EQ(elastic.stats.factorisations, 1);
  EXPECT_NE(tangent.log.find("(same matrix as the last factorisation: factors reused)"), std::string::npos);
  EXPECT_EQ(elastic.stats.newton_iterations, tangent.stats.newton_iterations);
  EXPECT_NE(elastic.log.find("(factorisation of the elastic matrix reused)"), std::string::npos);
  ASSERT_EQ(elastic.steps.size(), tangent.steps.size());
  for (size_t i = 1; i < tangent.steps.size(); ++i)
    EXPECT_NEAR(dy(elastic.steps[i]), dy(tangent.steps[i]), 1e-12 * std::abs(dy(tangent.steps[i])));
}

TEST(MatrixPolicy, ElasticMatrixWithContactIsABug) {
  // STAT_NON_LINE refuses MATRICE='ELASTIQUE' with contact; reaching the engine with it is a bug.
  Problem p(kPolicyForce);
  AtanSpring spring(kSpring);
  std::ostringstream sink;
  Log log(sink, 0);
  NewtonOptions options;
  options.elastic_matrix = true;
  EXPECT_THROW(StaticSolver(p.model, p.loads, options, &spring, log), InternalError);
}

/// The spring declared indefinite, as a contact hook with multipliers declares its system.
class IndefiniteSpring : public AtanSpring {
 public:
  using AtanSpring::AtanSpring;
  MatrixKind matrix_kind() const override { return MatrixKind::SymmetricIndefinite; }
};

TEST(MatrixPolicy, CholmodGivesWayAndSaysSoOnceARun) {
  Problem p(kPolicyForce);
  IndefiniteSpring spring(kSpring);
  std::ostringstream sink;
  Log log(sink, 1);
  NewtonOptions options;  // Cholmod, as SOLVEUR METHODE = 'AUTO', 'CHOLMOD', 'LDLT' or 'MULT_FRONT'
  StaticSolver solver(p.model, p.loads, options, &spring, log);
  const auto steps = solver.run(kInstants);
  const std::string text = sink.str();
  // A process alone: the saddle-point backend, and UMFPACK behind it for a small system (it
  // needs no MPI start-up; MUMPS from 1e4 unknowns). This spring has no multiplier, so
  // UMFPACK factorises it.
  const std::string note =
      "CHOLMOD cannot factorise an indefinite system; CHOLMOD factorises the Schur complement of its multipliers "
      "and GMRES solves it (UMFPACK if that gives way)";
  const auto first = text.find(note);
  ASSERT_NE(first, std::string::npos) << text;
  EXPECT_EQ(text.find(note, first + 1), std::string::npos) << "said more than once:\n" << text;
  EXPECT_GT(solver.stats().factorisations, 2);  // several factorisations, one note
  const double root = exact_root(elastic_stiffness(), kPolicyForce);
  EXPECT_NEAR(dy(steps.back()), root, 1e-6 * root);
}

}  // namespace
}  // namespace lunaster::engine
