// Mortar contact through the production Newton driver: the SSNP121 2D scene on
// non-matching meshes (exact to round-off), quadratic master, bimaterial, rotated scene,
// penalty floor, the SPD system, and an active set that has to move.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "engine/contact/mortar_problem.hpp"
#include "two_blocks.hpp"

namespace {

using namespace contact_test;
using lunaster::engine::contact::MortarProblem;

ContactDefinition mortar_definition(const TwoBlocks& tb, ContactMethod method, ContactInit init, double coef) {
  ContactDefinition def;
  def.method = method;
  ContactZone zone;
  zone.slave_cells = tb.ab;
  zone.master_cells = tb.ef;
  zone.init = init;
  // As DEFI_CONT reads COEF_CONT: the penalty of PENALISATION, LAGRANGIEN's complementarity constant.
  (method == ContactMethod::MortarPenalty ? zone.coef_pena : zone.coef_cont) = coef;
  def.zones.push_back(zone);
  def.modulus = 2e6;
  return def;
}

struct MortarRun {
  SolveResult result;
  NodalField depl;
  NodalField depl0;  ///< the initial state's (NUME_ORDRE 0)
  SolverStats stats;
  std::string log;
};

MortarRun run_mortar(const FeModel& model, const std::vector<Imposed>& imposed, MortarProblem& hook) {
  std::ostringstream out;
  lunaster::Log log(out, 1);
  MechanicalLoads loads;
  loads.multipliers.push_back([](double t) { return t; });
  for (const auto& d : imposed) loads.dirichlet.push_back({d.node, d.component, d.value, 0});
  NewtonOptions options;
  options.resi_glob_rela = 1e-10;
  options.iter_glob_maxi = 25;
  options.solver = SolverKind::Cholmod;
  StaticSolver solver(model, loads, options, &hook, log);
  const std::vector<ResultStep> steps = solver.run({0.0, 1.0});
  MortarRun run;
  run.result.dofs = solver.dofs();
  run.depl = steps.back().nodal.at("DEPL");
  run.depl0 = steps.front().nodal.at("DEPL");
  run.stats = solver.stats();
  run.log = out.str();
  return run;
}

double component(const MortarRun& r, int node, const char* cmp) {
  return r.depl.value(node, r.depl.component_index(cmp));
}

/// Largest relative error of LAGS_C and DY over the slave nodes against the uniform solution.
void expect_uniform(const MortarRun& run, const MortarProblem& hook, double pressure, double dy, double tol) {
  ASSERT_FALSE(hook.rows().empty());
  double worst_p = 0.0, worst_u = 0.0;
  for (const auto& row : hook.rows()) {
    worst_p = std::max(worst_p, std::abs(component(run, row.node, "LAGS_C") - pressure) / std::abs(pressure));
    worst_u = std::max(worst_u, std::abs(component(run, row.node, "DY") - dy) / std::abs(dy));
  }
  EXPECT_LT(worst_p, tol);
  EXPECT_LT(worst_u, tol);
}

TEST(MortarProblem, NonMatchingPatchTestIsExactAndSolvedByCholesky) {
  const TwoBlocks tb = make_two_blocks(12, 11, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  MortarProblem hook(mortar_definition(tb, ContactMethod::MortarLagrange, ContactInit::No, 100.0), tb.mesh, 2);
  const MortarRun run = run_mortar(model, displacement_bcs(tb), hook);
  EXPECT_EQ(hook.rows().size(), 13u);  // every slave node of AB is covered
  expect_uniform(run, hook, -1e5, -0.05, 1e-11);
  // The eliminated system is SPD: CHOLMOD factorised it, MUMPS was never called in.
  EXPECT_EQ(run.log.find("MUMPS"), std::string::npos) << run.log;
  // CONTACT_INIT='NON': one solve without contact, one with the settled active set.
  EXPECT_LE(run.stats.factorisations, 2);
  // The initial state has the components of the later steps (one list per MED field), LAGS_C
  // zero at the slave nodes: IMPR_RESU FORMAT='MED' used to stop on the difference.
  EXPECT_EQ(run.depl0.components, run.depl.components);
  const int lags = run.depl0.component_index("LAGS_C");
  ASSERT_GE(lags, 0);
  for (const auto& row : hook.rows()) {
    ASSERT_TRUE(run.depl0.has(row.node, lags)) << "slave node " << row.node;
    EXPECT_EQ(run.depl0.value(row.node, lags), 0.0);
  }
}

// The law, not the method named in the definition, decides how the rows are held: the
// penalty definition with the complementarity law is exact, the Lagrange one with the penalty
// law gives the penalty floor; a law whose multipliers enter the displacement equations needs
// LAGS_C unknowns, which dual rows do not have.
TEST(MortarProblem, TheLawDecidesHowTheRowsAreHeld) {
  using namespace lunaster::engine::contact;
  const TwoBlocks tb = make_two_blocks(12, 11, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  ContactDefinition def = mortar_definition(tb, ContactMethod::MortarPenalty, ContactInit::No, 1e9);
  def.zones[0].coef_cont = 100.0;
  MortarProblem exact(def, tb.mesh, 2, make_complementarity_law());
  expect_uniform(run_mortar(model, displacement_bcs(tb), exact), exact, -1e5, -0.05, 1e-11);
  def.method = ContactMethod::MortarLagrange;
  MortarProblem penalty(def, tb.mesh, 2, make_penalty_law());
  const MortarRun run = run_mortar(model, displacement_bcs(tb), penalty);
  const double p = 0.1 * 2e6 / (2.0 + 2e6 / 1e9);  // the floor of PenaltyGivesItsFloorAndNoWorse
  expect_uniform(run, penalty, -p, -0.05 - 0.5 * p / 1e9, 1e-10);
  EXPECT_THROW(MortarProblem(def, tb.mesh, 2, make_augmented_lagrangian_law()), lunaster::InternalError);
  EXPECT_THROW(MortarProblem(def, tb.mesh, 2, make_active_set_law()), lunaster::InternalError);
}

TEST(MortarProblem, ASlaveNodeOfTwoZonesIsRefused) {
  // AB split into its left and right halves, each a zone against EF: the node at x = 0 ends a
  // cell of each zone and would carry two conditions.
  const TwoBlocks tb = make_two_blocks(12, 11, false);
  ContactDefinition def = mortar_definition(tb, ContactMethod::MortarLagrange, ContactInit::Yes, 100.0);
  ContactZone right = def.zones[0];
  def.zones[0].slave_cells.assign(tb.ab.begin(), tb.ab.begin() + 6);
  right.slave_cells.assign(tb.ab.begin() + 6, tb.ab.end());
  def.zones.push_back(right);
  try {
    MortarProblem hook(def, tb.mesh, 2);
    FAIL() << "a slave node in two zones was accepted";
  } catch (const lunaster::DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("belongs to contact zones 1 and 2"), std::string::npos) << e.what();
  }
}

TEST(MortarProblem, QuadraticMasterIsExact) {
  const TwoBlocks tb = make_two_blocks(12, 11, true);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  MortarProblem hook(mortar_definition(tb, ContactMethod::MortarLagrange, ContactInit::Yes, 100.0), tb.mesh, 2);
  const MortarRun run = run_mortar(model, displacement_bcs(tb), hook);
  expect_uniform(run, hook, -1e5, -0.05, 1e-11);
  EXPECT_EQ(run.stats.factorisations, 1);  // CONTACT_INIT='OUI': the active set is right from the start
}

TEST(MortarProblem, BimaterialPatchTestIsExact) {
  const TwoBlocks tb = make_two_blocks(7, 12, false);
  FeModel model = make_model(tb.mesh, 2e6, 0.0);
  model.materials.push_back({6e6, 0.0, 0.0});
  for (int c = 0; c < tb.mesh.n_cells(); ++c) {
    if (model.material[c] < 0) continue;
    const int* nodes = tb.mesh.cell(c);
    double y = 0.0;
    for (int a = 0; a < 4; ++a) y += tb.mesh.node(nodes[a])[1] / 4;
    if (y < 0.0) model.material[c] = 1;  // lower block three times stiffer
  }
  ContactDefinition def = mortar_definition(tb, ContactMethod::MortarLagrange, ContactInit::Interpenetrated, 100.0);
  def.modulus = 6e6;
  MortarProblem hook(def, tb.mesh, 2);
  const MortarRun run = run_mortar(model, displacement_bcs(tb), hook);
  // Springs in series: p = 0.1 / (1/E1 + 1/E2); the interface moves by -p/E2.
  const double p = 0.1 / (1.0 / 2e6 + 1.0 / 6e6);
  expect_uniform(run, hook, -p, -p / 6e6, 1e-11);
}

TEST(MortarProblem, PenaltyGivesItsFloorAndNoWorse) {
  const TwoBlocks tb = make_two_blocks(12, 11, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  const double kappa = 1e9;
  MortarProblem hook(mortar_definition(tb, ContactMethod::MortarPenalty, ContactInit::No, kappa), tb.mesh, 2);
  const MortarRun run = run_mortar(model, displacement_bcs(tb), hook);
  // Two unit-height blocks and a penalty spring in series: p = 0.1 E / (2 + E / kappa),
  // E / (2 kappa) = 1e-3 below the exact pressure.
  const double p = 0.1 * 2e6 / (2.0 + 2e6 / kappa);
  expect_uniform(run, hook, -p, -0.05 - 0.5 * p / kappa, 1e-10);
  EXPECT_NEAR(p / 1e5 - 1.0, -1e-3, 1e-6);
  EXPECT_EQ(run.log.find("MUMPS"), std::string::npos) << run.log;
}

TEST(MortarProblem, RotatedSceneIsExact) {
  // The whole scene turned by 30 degrees: the interface normal is no coordinate axis.
  TwoBlocks tb = make_two_blocks(12, 11, false);
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (int n = 0; n < tb.mesh.n_nodes(); ++n) {
    double* x = &tb.mesh.coords[3 * static_cast<size_t>(n)];
    const double x0 = x[0], y0 = x[1];
    x[0] = c * x0 - s * y0, x[1] = s * x0 + c * y0;
  }
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  // CD pushed by 0.1 along the rotated vertical, both components imposed; GH fixed.
  std::vector<Imposed> bcs;
  for (int n : tb.cd_nodes) bcs.push_back({n, DX, 0.1 * s}), bcs.push_back({n, DY, -0.1 * c});
  for (int n : tb.gh_nodes) bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, 0.0});
  MortarProblem hook(mortar_definition(tb, ContactMethod::MortarLagrange, ContactInit::Yes, 100.0), tb.mesh, 2);
  const MortarRun run = run_mortar(model, bcs, hook);
  double worst_p = 0.0, worst_u = 0.0;
  for (const auto& row : hook.rows()) {
    worst_p = std::max(worst_p, std::abs(component(run, row.node, "LAGS_C") + 1e5) / 1e5);
    worst_u = std::max(worst_u, std::hypot(component(run, row.node, "DX") - 0.05 * s,
                                           component(run, row.node, "DY") + 0.05 * c) / 0.05);
  }
  EXPECT_LT(worst_p, 1e-11);
  EXPECT_LT(worst_u, 1e-11);
}

TEST(MortarProblem, ActiveSetMovesInsideNewtonAndSettles) {
  // CD tilted: DY = -0.1 at x = +1, +0.05 at x = -1 (lifted): the left part of the
  // interface opens. Starting from every node in contact, the semi-smooth Newton has to
  // release the left nodes; it ends with pressures >= 0 where active and gaps >= 0 elsewhere.
  const TwoBlocks tb = make_two_blocks(12, 11, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  std::vector<Imposed> bcs;
  for (int n : tb.cd_nodes) {
    const double x = tb.mesh.node(n)[0];
    bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, -0.1 * (x + 1) / 2 + 0.05 * (1 - x) / 2});
  }
  for (int n : tb.gh_nodes) bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, 0.0});
  ContactDefinition def = mortar_definition(tb, ContactMethod::MortarLagrange, ContactInit::Yes, 100.0);
  def.reac_geom = GeometryUpdate::None;  // one pairing: the Newton iterations are the active set's
  MortarProblem hook(def, tb.mesh, 2);
  const MortarRun run = run_mortar(model, bcs, hook);
  EXPECT_GT(hook.n_status_changes(), 0);
  int n_active = 0, n_open = 0;
  for (size_t i = 0; i < hook.rows().size(); ++i) {
    const auto& row = hook.rows()[i];
    const double lags = component(run, row.node, "LAGS_C");
    if (row.active) {
      ++n_active;
      EXPECT_LE(lags, 1e-6) << "tension at an active node";
    } else {
      ++n_open;
      EXPECT_DOUBLE_EQ(lags, 0.0);
    }
  }
  EXPECT_GT(n_active, 0);
  EXPECT_GT(n_open, 0);
  // Finite termination of the semi-smooth Newton on a linear problem: the statuses settle
  // in a few solves (3 here), all inside one Newton loop.
  EXPECT_LE(run.stats.newton_iterations, 4) << run.log;
  EXPECT_EQ(run.stats.contact_passes, 1) << run.log;
  // The rate: on this linear problem a Newton step with the right active set is exact, so the
  // residual table ends with one drop from a finite residual to round-off (faster than any
  // quadratic rate: quadratic from 1e-3 would give 1e-6). The relative residuals in order:
  std::vector<double> relative;
  std::istringstream lines(run.log);
  for (std::string line; std::getline(lines, line);) {
    int iter = 0;
    double rel = 0.0, abs = 0.0;
    if (std::sscanf(line.c_str(), " | %d | %lf | %lf |", &iter, &rel, &abs) == 3) relative.push_back(rel);
  }
  ASSERT_GE(relative.size(), 3u) << run.log;
  EXPECT_LT(relative.back(), 1e-12) << run.log;
  EXPECT_GT(relative[relative.size() - 2], 1e-6) << "the active set settled before the last solve: " << run.log;
}

/// The 4-on-3 blocks, re-paired at every geometric change, and displacements that slide the
/// upper block (whose 5 x 5 nodes come first) over the lower one.
struct SlidingBlocks {
  TwoBlocks tb = make_two_blocks(4, 3, false);
  DofMap dofs;
  std::unique_ptr<MortarProblem> hook;
  SlidingBlocks() : dofs(tb.mesh, make_model(tb.mesh, 2e6, 0.0).volume_cells(), 2) {
    ContactDefinition def = mortar_definition(tb, ContactMethod::MortarLagrange, ContactInit::Yes, 100.0);
    def.reac_geom = GeometryUpdate::Automatic;
    def.resi_geom = 1e-12;
    hook = std::make_unique<MortarProblem>(def, tb.mesh, 2);
    hook->add_dofs(dofs);
  }
  Vector moved(double ux_up, double ux_low, double uy) const {
    Vector u = Vector::Zero(dofs.n_dofs());
    for (int node = 0; node < tb.mesh.n_nodes(); ++node) {
      u[dofs.dof(node, DX)] = node < 5 * 5 ? ux_up : ux_low;
      u[dofs.dof(node, DY)] = uy;
    }
    return u;
  }
};

TEST(MortarProblem, SurfacesThatMovedAsOneKeepTheirRowsWithoutIntegratingThem) {
  SlidingBlocks blocks;
  MortarProblem& hook = *blocks.hook;
  hook.begin_step(blocks.moved(0.0, 0.0, 0.0), quiet_log());
  ASSERT_EQ(hook.n_row_builds(), 1);
  const auto rows = hook.rows();
  // Both surfaces translated together: settled, the rows kept, nothing integrated.
  EXPECT_TRUE(hook.settle(blocks.moved(0.13, 0.13, -0.02), quiet_log()));
  EXPECT_EQ(hook.n_row_builds(), 1);
  ASSERT_EQ(hook.rows().size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(hook.rows()[i].node, rows[i].node);
    EXPECT_EQ(hook.rows()[i].coef, rows[i].coef);
  }
  // The upper block slid along the interface: the rows are integrated again, and change.
  EXPECT_FALSE(hook.settle(blocks.moved(0.23, 0.13, -0.02), quiet_log()));
  EXPECT_EQ(hook.n_row_builds(), 2);
  EXPECT_EQ(hook.n_pairings(), 2);
}

TEST(MortarProblem, ASplitStepStartsFromThePairingAndStatusesOfTheStepStart) {
  // A failed attempt re-paired the sliding surfaces and changed statuses; the driver then
  // restores the snapshot taken at the step's start. Mortar keeps the last converged pairing
  // (begin_step pairs only once), so the snapshot must bring back the rows themselves.
  SlidingBlocks blocks;
  MortarProblem& hook = *blocks.hook;
  const Vector at_rest = blocks.moved(0.0, 0.0, 0.0);
  const ContactSnapshot before_first = hook.snapshot();
  hook.begin_step(at_rest, quiet_log());  // first step: paired, all active (CONTACT_INIT)
  const int active = hook.n_active();
  ASSERT_GT(active, 0);
  const ContactSnapshot start = hook.snapshot();  // the next step's start
  const std::vector<lunaster::engine::contact::MortarRow> rows = hook.rows();
  const auto masters = hook.master_terms();
  // The failed attempt: the upper block slid by 0.4 of a cell, re-paired, statuses changed.
  hook.begin_step(at_rest, quiet_log());
  EXPECT_FALSE(hook.settle(blocks.moved(0.1, 0.0, 0.0), quiet_log()));
  ASSERT_EQ(hook.n_pairings(), 2);
  ASSERT_NE(hook.master_terms(), masters);
  hook.restore(start);
  ASSERT_EQ(hook.rows().size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(hook.rows()[i].node, rows[i].node);
    EXPECT_EQ(hook.rows()[i].coef, rows[i].coef);
    EXPECT_EQ(hook.rows()[i].active, rows[i].active);
  }
  EXPECT_EQ(hook.master_terms(), masters);
  EXPECT_EQ(hook.n_active(), active);
  // The next begin_step keeps that pairing (no new one), as after a converged step.
  hook.begin_step(at_rest, quiet_log());
  EXPECT_EQ(hook.n_pairings(), 2);
  EXPECT_EQ(hook.master_terms(), masters);
  // Restoring the state from before the first step pairs again and applies CONTACT_INIT.
  hook.restore(before_first);
  hook.begin_step(blocks.moved(0.1, 0.0, 0.0), quiet_log());
  EXPECT_EQ(hook.n_pairings(), 3);
  EXPECT_EQ(hook.n_active(), static_cast<int>(hook.rows().size()));
}

}  // namespace
