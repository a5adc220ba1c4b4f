// The shared contact part (ContactProblem): condensation of multipliers that no active
// point couples to the displacements, their recovery after the solve, and the snapshot
// of statuses that a split step starts from. Solves go through the production driver.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "engine/contact/contact_problem.hpp"
#include "two_blocks.hpp"

using namespace contact_test;
using lunaster::engine::contact::ContactProblem;

namespace {


std::unique_ptr<ContactProblem> problem(const ContactDefinition& def, const Mesh& mesh, bool condense) {
  std::unique_ptr<ContactProblem> p(dynamic_cast<ContactProblem*>(make_contact_hook(def, mesh, 2).release()));
  p->allow_condensation(condense);
  return p;
}

}  // namespace

TEST(ContactCondensation, PenaltySolvesAnSpdSystemAndRecoversTheSameLagsC) {
  const TwoBlocks tb = make_two_blocks(12, 11, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  const ContactDefinition def = zone_ab_on_ef(tb, ContactMethod::ContinuousPenalty, ContactInit::No);
  auto condensed = problem(def, tb.mesh, true);
  auto full = problem(def, tb.mesh, false);
  const SolveResult a = solve(model, displacement_bcs(tb), {}, *condensed, quiet_log());
  const SolveResult b = solve(model, displacement_bcs(tb), {}, *full, quiet_log());
  // Penalty never couples LAGS_C into the displacement equations: always condensed, SPD.
  EXPECT_EQ(condensed->matrix_kind(), MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(condensed->condensed_equations().size(), condensed->multiplier_nodes().size());
  EXPECT_EQ(full->matrix_kind(), MatrixKind::SymmetricIndefinite);
  EXPECT_TRUE(full->condensed_equations().empty());
  // The same answer either way, to round-off, on every unknown (LAGS_C included).
  ASSERT_EQ(a.u.size(), b.u.size());
  double lags_max = 0.0;
  for (int node : condensed->multiplier_nodes()) lags_max = std::max(lags_max, std::abs(lags_c(a, node)));
  EXPECT_GT(lags_max, 5e4);  // the blocks are pressed together
  for (int eq = 0; eq < a.u.size(); ++eq) {
    const double scale = a.dofs.component_of(eq) == LAGS_C ? lags_max : 0.1;
    EXPECT_NEAR(a.u[eq], b.u[eq], 1e-9 * scale) << "equation " << eq;
  }
  // The recovered multipliers satisfy their own rows.
  Vector r = Vector::Zero(a.u.size());
  std::vector<Triplet> unused;
  condensed->add_to_system(a.u, unused, r);
  for (int node : condensed->multiplier_nodes())
    EXPECT_NEAR(r[a.dofs.dof(node, LAGS_C)], 0.0, 1e-10 * lags_max) << "LAGS_C row of node " << node;
}

TEST(ContactCondensation, AugmentedLagrangianIsCondensedOnlyWhileNoPointIsActive) {
  const TwoBlocks tb = make_two_blocks(4, 3, false);
  auto p = problem(zone_ab_on_ef(tb, ContactMethod::Continuous, ContactInit::No), tb.mesh, true);
  DofMap dofs(tb.mesh, make_model(tb.mesh, 2e6, 0.0).volume_cells(), 2);
  p->add_dofs(dofs);
  p->begin_step(Vector::Zero(dofs.n_dofs()), quiet_log());
  EXPECT_EQ(p->n_active(), 0);
  EXPECT_EQ(p->matrix_kind(), MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(p->condensed_equations().size(), p->multiplier_nodes().size());
  p->set_all_active(true);
  EXPECT_GT(p->n_active(), 0);
  EXPECT_EQ(p->matrix_kind(), MatrixKind::SymmetricIndefinite);
  EXPECT_TRUE(p->condensed_equations().empty());
}

TEST(ContactSnapshot, RestoresTheStatusesOfTheStepStart) {
  const TwoBlocks tb = make_two_blocks(4, 3, false);
  auto p = problem(zone_ab_on_ef(tb, ContactMethod::Continuous, ContactInit::Yes), tb.mesh, true);
  DofMap dofs(tb.mesh, make_model(tb.mesh, 2e6, 0.0).volume_cells(), 2);
  p->add_dofs(dofs);
  const ContactSnapshot before_first = p->snapshot();  // nothing paired yet
  p->begin_step(Vector::Zero(dofs.n_dofs()), quiet_log());
  const int active = p->n_active();
  ASSERT_GT(active, 0);
  const ContactSnapshot start = p->snapshot();
  p->set_all_active(false);
  EXPECT_EQ(p->n_active(), 0);
  p->restore(start);
  EXPECT_EQ(p->n_active(), active);
  // Restoring the state from before the first pairing makes the next step apply
  // CONTACT_INIT again (here 'OUI': every paired point active).
  p->set_all_active(false);
  p->restore(before_first);
  p->begin_step(Vector::Zero(dofs.n_dofs()), quiet_log());
  EXPECT_EQ(p->n_active(), active);
}

namespace {

/// The pairing of `p` against that of a problem paired afresh at u (same definition and mesh).
void expect_fresh_pairing(const ContactProblem& p, const ContactDefinition& def, const TwoBlocks& tb, const Vector& u) {
  auto fresh = problem(def, tb.mesh, true);
  DofMap dofs(tb.mesh, make_model(tb.mesh, 2e6, 0.0).volume_cells(), 2);
  fresh->add_dofs(dofs);
  fresh->begin_step(u, quiet_log());
  ASSERT_EQ(p.points().size(), fresh->points().size());
  for (size_t i = 0; i < p.points().size(); ++i) {
    const auto &a = p.points()[i], &b = fresh->points()[i];
    ASSERT_EQ(a.paired, b.paired) << "point " << i;
    if (!a.paired) continue;
    EXPECT_EQ(a.master_cell, b.master_cell) << "point " << i;
    EXPECT_NEAR(a.xi_master[0], b.xi_master[0], 1e-12) << "point " << i;
    EXPECT_NEAR(a.wjac, b.wjac, 1e-14) << "point " << i;
    EXPECT_NEAR(a.gap.value(u), b.gap.value(u), 1e-14) << "point " << i;
  }
}

}  // namespace

TEST(ContactPairing, KeepsThePairingOfPointsThatMovedAsOneAndOnlyThose) {
  const TwoBlocks tb = make_two_blocks(4, 3, false);  // non-matching: 4 cells on 3
  const ContactDefinition def = zone_ab_on_ef(tb, ContactMethod::Continuous, ContactInit::Yes);
  auto p = problem(def, tb.mesh, true);
  DofMap dofs(tb.mesh, make_model(tb.mesh, 2e6, 0.0).volume_cells(), 2);
  p->add_dofs(dofs);
  const int upper_nodes = 5 * 5;  // the upper block's nodes come first
  auto moved = [&](double ux_up, double uy_up, double ux_low, double uy_low) {
    Vector u = Vector::Zero(dofs.n_dofs());
    for (int node = 0; node < tb.mesh.n_nodes(); ++node) {
      const bool up = node < upper_nodes;
      u[dofs.dof(node, DX)] = up ? ux_up : ux_low;
      u[dofs.dof(node, DY)] = up ? uy_up : uy_low;
    }
    return u;
  };
  p->begin_step(Vector::Zero(dofs.n_dofs()), quiet_log());
  EXPECT_EQ(p->n_kept(), 0);  // nothing to keep at the first pairing
  const int n_points = static_cast<int>(p->points().size());
  ASSERT_GT(n_points, 0);
  // Both blocks translated together: every point keeps its pairing, which is the fresh one.
  const Vector together = moved(0.13, -0.02, 0.13, -0.02);
  const long version = p->pattern_version();
  p->begin_step(together, quiet_log());
  EXPECT_EQ(p->n_kept(), n_points);
  EXPECT_EQ(p->pattern_version(), version);  // the same terms: the driver keeps its system
  expect_fresh_pairing(*p, def, tb, together);
  // The upper block slid along the interface: no point keeps its pairing, every one is
  // projected again (a point sliding by a fifth of a master cell changes cell or xi).
  const Vector slid = moved(0.13 + 0.1, -0.02, 0.13, -0.02);
  p->begin_step(slid, quiet_log());
  EXPECT_EQ(p->n_kept(), 0);
  EXPECT_GT(p->pattern_version(), version);
  expect_fresh_pairing(*p, def, tb, slid);
  // One lower node moved alone: the points whose master neighbourhood holds it are projected
  // again, the others keep their pairing; all equal the fresh pairing.
  Vector bumped = slid;
  bumped[dofs.dof(tb.node_e, DY)] += 1e-3;
  p->begin_step(bumped, quiet_log());
  EXPECT_GT(p->n_kept(), 0);
  EXPECT_LT(p->n_kept(), n_points);
  expect_fresh_pairing(*p, def, tb, bumped);
}
