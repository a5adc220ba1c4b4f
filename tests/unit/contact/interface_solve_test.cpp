// Contact passes on the elastic factorisation kept for the run (InterfaceSolver, chosen by
// the driver for SOLVEUR METHODE='AUTO'): the same answer as the whole-system solve (MUMPS)
// for every law, through the production Newton driver, on the SSNP121 2D geometry refined
// until the contact surfaces are a small part of the model; and the whole-system solve
// when the elastic system alone is singular.
#include <cmath>

#include <gtest/gtest.h>

#include "two_blocks.hpp"

using namespace contact_test;

namespace {

constexpr double kSolveYoung = 2.0e6;


NewtonOptions auto_solver() {
  NewtonOptions o;
  o.auto_solver = true;  // SOLVEUR METHODE='AUTO'
  return o;
}

NewtonOptions whole_system() {
  NewtonOptions o;
  o.solver = SolverKind::Mumps;  // a deck naming its solver: every pass factorises the whole system
  return o;
}

void expect_same(const SolveResult& a, const SolveResult& b, const char* what) {
  ASSERT_EQ(a.u.size(), b.u.size());
  const double scale_u = b.u.cwiseAbs().maxCoeff();
  for (int eq = 0; eq < a.u.size(); ++eq)
    ASSERT_NEAR(a.u[eq], b.u[eq], 1e-9 * scale_u) << what << ", equation " << eq;
}

}  // namespace

TEST(ContactInterfaceSolve, EveryLawGivesTheWholeSystemAnswer) {
  const TwoBlocks tb = make_two_blocks(48, 44, false);
  const FeModel model = make_model(tb.mesh, kSolveYoung, 0.0);
  struct Case { ContactMethod method; ContactInit init; const char* name; };
  for (const Case& c : {Case{ContactMethod::Continuous, ContactInit::No, "CONTINUE, CONTACT_INIT='NON'"},
                        Case{ContactMethod::Continuous, ContactInit::Yes, "CONTINUE, CONTACT_INIT='OUI'"},
                        Case{ContactMethod::DiscreteLagrange, ContactInit::No, "CONTRAINTE"},
                        Case{ContactMethod::DiscretePenalty, ContactInit::No, "PENALISATION"}}) {
    SCOPED_TRACE(c.name);
    const ContactDefinition def = zone_ab_on_ef(tb, c.method, c.init);
    auto kept = make_contact_hook(def, tb.mesh, 2);
    const SolveResult r = solve(model, displacement_bcs(tb), {}, *kept, quiet_log(), auto_solver());
    auto whole = make_contact_hook(def, tb.mesh, 2);
    const SolveResult ref = solve(model, displacement_bcs(tb), {}, *whole, quiet_log(), whole_system());
    // The surfaces: 49 + 45 nodes, two components each, and the slave nodes' LAGS_C (none
    // for a law without multipliers).
    const int multipliers = c.method == ContactMethod::DiscretePenalty ? 0 : 49;
    EXPECT_EQ(r.stats.interface_equations, 2 * (49 + 45) + multipliers);
    EXPECT_EQ(ref.stats.interface_equations, 0);
    EXPECT_EQ(r.n_settle, ref.n_settle);
    expect_same(r, ref, c.name);
    // The interface displacement (exact -0.05 m): the node-to-segment methods miss the patch
    // test by design (percents at the corner A), CONTINUE's Simpson points do not.
    EXPECT_NEAR(dy(r, tb.node_a), -0.05, 0.05 * (c.method == ContactMethod::Continuous ? 1e-4 : 1e-2));
  }
}

TEST(ContactInterfaceSolve, ABodyHeldByContactAloneIsSolvedWhole) {
  // SSNP121 G: the upper block under pressure, held only by contact (and DX at one node):
  // without contact its stiffness is singular, so no elastic factorisation can be kept.
  const TwoBlocks tb = make_two_blocks(48, 44, false);
  const FeModel model = make_model(tb.mesh, kSolveYoung, 0.0);
  const ContactDefinition def = zone_ab_on_ef(tb, ContactMethod::Continuous, ContactInit::Yes);
  std::vector<Imposed> bcs = {{tb.cd_nodes[0], DX, 0.0}};
  for (int n : tb.gh_nodes) bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, 0.0});
  auto hook = make_contact_hook(def, tb.mesh, 2);
  const SolveResult r = solve(model, bcs, {{tb.cd, 1e5}}, *hook, quiet_log(), auto_solver());
  EXPECT_EQ(r.stats.interface_equations, 0);
  EXPECT_NEAR(lags_c(r, tb.node_a), -1e5, 1e5 * 1e-3);
}

TEST(ContactInterfaceSolve, TheNormalComponentsAloneWhereTheWholeSurfacesAreTooMany) {
  // SSNP121 A's geometry at 8 x 8 over 6 x 6 cells: the surfaces' 41 equations (9 + 7 nodes,
  // two components each, and 9 LAGS_C) are more than a twentieth of the 260 unknowns. The
  // pairing's normals reach DY alone (the interface is square to y), so the interface is their
  // DY and the LAGS_C: 25 equations, and the answer is the whole system's. With
  // CONTACT_INIT='NON' the first solve has no contact term: the normals decide alone.
  const TwoBlocks tb = make_two_blocks(8, 6, false);
  const FeModel model = make_model(tb.mesh, kSolveYoung, 0.0);
  for (ContactInit init : {ContactInit::Yes, ContactInit::No}) {
    SCOPED_TRACE(init == ContactInit::Yes ? "CONTACT_INIT='OUI'" : "CONTACT_INIT='NON'");
    const ContactDefinition def = zone_ab_on_ef(tb, ContactMethod::Continuous, init);
    auto kept = make_contact_hook(def, tb.mesh, 2);
    const SolveResult r = solve(model, displacement_bcs(tb), {}, *kept, quiet_log(), auto_solver());
    auto whole = make_contact_hook(def, tb.mesh, 2);
    const SolveResult ref = solve(model, displacement_bcs(tb), {}, *whole, quiet_log(), whole_system());
    EXPECT_EQ(r.stats.interface_equations, 9 + 7 + 9);
    EXPECT_EQ(ref.stats.interface_equations, 0);
    expect_same(r, ref, "normal components");
    EXPECT_NEAR(lags_c(r, tb.node_a), -1e5, 1e5 * 1e-6);
  }
}

TEST(ContactInterfaceSolve, ATermOnAnotherComponentLaterGivesTheInterfaceUp) {
  // The same small geometry, CD pushed down by 0.08 to 0.12 m from one end to the other: the
  // first pass (flat surfaces) reaches DY alone, so the interface is their DY and LAGS_C;
  // the re-pairing on the tilted surfaces reaches DX too. The driver then gives the interface
  // solver up and solves the whole system from that pass on, with the whole system's answer.
  const TwoBlocks tb = make_two_blocks(8, 6, false);
  const FeModel model = make_model(tb.mesh, kSolveYoung, 0.0);
  std::vector<Imposed> bcs;
  for (int n : tb.cd_nodes) {
    const double x = tb.mesh.coords[3 * static_cast<std::size_t>(n)];
    bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, -0.08 - 0.02 * x});
  }
  for (int n : tb.gh_nodes) bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, 0.0});
  const ContactDefinition def = zone_ab_on_ef(tb, ContactMethod::Continuous, ContactInit::Yes);
  std::ostringstream out;
  const lunaster::Log log(out, 1);
  auto kept = make_contact_hook(def, tb.mesh, 2);
  const SolveResult r = solve(model, bcs, {}, *kept, log, auto_solver());
  auto whole = make_contact_hook(def, tb.mesh, 2);
  const SolveResult ref = solve(model, bcs, {}, *whole, quiet_log(), whole_system());
  EXPECT_NE(out.str().find("elastic system factorised with the 25 equations"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("a contact term outside the surfaces' equations"), std::string::npos) << out.str();
  EXPECT_EQ(r.stats.interface_equations, 0);
  expect_same(r, ref, "interface given up");
}
