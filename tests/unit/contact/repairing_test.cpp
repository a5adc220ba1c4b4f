// A contact pass after a new pairing starts from the converged state of the previous pass.
// When the new pairing leaves the residual where that pass converged (a flat interface
// translated: the same projections), the pass needs no solve; when it changes the residual,
// Newton solves as before. The SSNP121 2D blocks pressed together, run with two pairings
// (REAC_GEOM='CONTROLE', NB_ITER_GEOM=2, as SSNP121 A) and with one (REAC_GEOM='SANS').
#include <gtest/gtest.h>

#include "two_blocks.hpp"

using namespace contact_test;

namespace {

SolveResult press(const TwoBlocks& tb, ContactMethod method, GeometryUpdate update) {
  const FeModel model = make_model(tb.mesh, 2.0e6, 0.0);
  ContactDefinition def = zone_ab_on_ef(tb, method, ContactInit::Yes);
  def.reac_geom = update;
  const auto hook = make_contact_hook(def, tb.mesh, 2);
  const lunaster::Log log = quiet_log();
  return solve(model, displacement_bcs(tb), {}, *hook, log);
}

}  // namespace

TEST(Repairing, ATranslatedFlatInterfaceNeedsNoSecondSolve) {
  for (ContactMethod method : {ContactMethod::Continuous, ContactMethod::DiscreteLagrange}) {
    const TwoBlocks tb = make_two_blocks(8, 8, false);
    const SolveResult twice = press(tb, method, GeometryUpdate::Controlled);
    const SolveResult once = press(tb, method, GeometryUpdate::None);
    SCOPED_TRACE(method == ContactMethod::Continuous ? "CONTINUE" : "CONTRAINTE");
    EXPECT_GT(twice.stats.contact_passes, once.stats.contact_passes);  // it did pair again
    // The second pairing's residual is the first's: no solve (before: one more Newton iteration).
    EXPECT_EQ(twice.stats.newton_iterations, once.stats.newton_iterations);
    EXPECT_EQ(twice.stats.factorisations, once.stats.factorisations);
    // The same solution, SSNP121's: DY = -0.05 at A, LAGS_C = -1e5 at O.
    EXPECT_NEAR(dy(twice, tb.node_a), -0.05, 1e-12);
    EXPECT_NEAR(dy(twice, tb.node_a), dy(once, tb.node_a), 1e-14);
    if (method == ContactMethod::Continuous) {
      EXPECT_NEAR(lags_c(twice, tb.node_o) / -1.0e5, 1.0, 1e-10);
    }
  }
}

TEST(Repairing, APairingThatChangesTheResidualIsSolved) {
  // Non-matching blocks with a penalty: the second pairing projects the deformed slave nodes
  // on the deformed master edges, and the contact forces change by more than round-off.
  const TwoBlocks tb = make_two_blocks(8, 7, false);
  const SolveResult twice = press(tb, ContactMethod::DiscretePenalty, GeometryUpdate::Controlled);
  const SolveResult once = press(tb, ContactMethod::DiscretePenalty, GeometryUpdate::None);
  EXPECT_GT(twice.stats.contact_passes, once.stats.contact_passes);
  EXPECT_GT(twice.stats.newton_iterations, once.stats.newton_iterations);
}
