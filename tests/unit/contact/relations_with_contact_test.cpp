// Linear relations (LIAISON_DDL, engine/nonlinear/relations_hook.hpp) in the Newton system,
// alone and beside each contact method. The SSNP121 A scene with the loading plate written as
// relations: only the first node of CD has DY = -0.1 imposed, and the DY of every other CD node
// is tied to it (DY(n) - DY(first) = 0).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "engine/assembly/linear_relations.hpp"
#include "engine/nonlinear/relations_hook.hpp"
#include "two_blocks.hpp"

namespace {

using namespace contact_test;

/// SSNP121 A's conditions but DY of CD, which only its first node gets; the relations tie
/// the others to it.
struct PlateByRelations {
  std::vector<Imposed> imposed;
  std::vector<LinearRelation> relations;
};

PlateByRelations plate_by_relations(const TwoBlocks& tb) {
  PlateByRelations p;
  for (int n : tb.cd_nodes) p.imposed.push_back({n, DX, 0.0});
  p.imposed.push_back({tb.cd_nodes[0], DY, -0.1});
  for (int n : tb.gh_nodes) p.imposed.push_back({n, DX, 0.0}), p.imposed.push_back({n, DY, 0.0});
  for (size_t i = 1; i < tb.cd_nodes.size(); ++i) {
    LinearRelation r;
    r.terms = {{tb.cd_nodes[i], DY, 1.0}, {tb.cd_nodes[0], DY, -1.0}};
    p.relations.push_back(r);
  }
  return p;
}

TEST(RelationsHook, TieTheLoadingPlateBesideEachContactMethodAsDirichletConditionsWould) {
  // Each method gives with the relations what it gives with DY imposed on every CD node (the
  // relations hold to round-off, and a contact hook reads the residual they add to); mortar,
  // exact on this non-matching interface, gives SSNP121 A's DY = -0.05 m on AB.
  const TwoBlocks tb = make_two_blocks(12, 11, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  const PlateByRelations plate = plate_by_relations(tb);
  MechanicalLoads loads;
  loads.multipliers.push_back([](double t) { return t; });
  struct Case { const char* name; ContactMethod method; ContactInit init; };
  for (const Case c : {Case{"CONTINUE", ContactMethod::Continuous, ContactInit::Interpenetrated},
                       Case{"CONTRAINTE", ContactMethod::DiscreteLagrange, ContactInit::Interpenetrated},
                       Case{"mortar", ContactMethod::MortarLagrange, ContactInit::Yes}}) {
    ContactDefinition def = zone_ab_on_ef(tb, c.method, c.init);
    def.modulus = 2e6;
    auto plain = make_contact_hook(def, tb.mesh, 2);
    std::ostringstream out;
    lunaster::Log log(out, 1);
    SolveResult ref;
    ASSERT_NO_THROW(ref = solve(model, displacement_bcs(tb), {}, *plain, log)) << c.name << "\n" << out.str();
    // Multipliers, and (but beside mortar, which eliminates unknowns itself) eliminated relations.
    for (bool eliminate : {false, true}) {
      if (eliminate && c.method == ContactMethod::MortarLagrange) continue;
      const std::string what = std::string(c.name) + (eliminate ? ", eliminated" : ", multipliers");
      auto tied = make_relations_hook(plate.relations, loads.multipliers, make_contact_hook(def, tb.mesh, 2), eliminate);
      EXPECT_TRUE(tied->has_contact());
      SolveResult r;
      ASSERT_NO_THROW(r = solve(model, plate.imposed, {}, *tied, log)) << what << "\n" << out.str();
      // The same numbering but for the relations' multipliers, numbered last.
      ASSERT_EQ(r.dofs.n_dofs(), ref.dofs.n_dofs() + (eliminate ? 0 : static_cast<int>(plate.relations.size())))
          << what;
      for (int eq = 0; eq < ref.dofs.n_dofs(); ++eq) {
        const double scale = ref.dofs.component_of(eq) == LAGS_C ? 1e5 : 0.1;
        EXPECT_NEAR(r.u[eq], ref.u[eq], 1e-9 * scale) << what << " equation " << eq;
      }
      for (int n : tb.cd_nodes) EXPECT_NEAR(r.u[r.dofs.dof(n, DY)], -0.1, 1e-12) << what;
      if (c.method == ContactMethod::MortarLagrange) {
        for (int n : {tb.node_a, tb.node_o, tb.node_b}) EXPECT_NEAR(dy(r, n) / -0.05, 1.0, 1e-12) << what;
      }
      EXPECT_GT(r.n_settle, 0) << what;  // its contact passes still run
    }
  }
}

TEST(RelationsHook, AloneTheyHoldWhatDirichletConditionsWouldAndRunNoContactPass) {
  // The upper block alone, pressed by the plate written as relations onto a fixed base: GH's
  // conditions move to AB (DY = 0), so DY(CD) = -0.1 gives SIYY = -E 0.1.
  const TwoBlocks tb = make_two_blocks(4, 3, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.0);
  PlateByRelations plate = plate_by_relations(tb);
  for (const int n : tb.mesh.nodes_of_cells(tb.ab)) plate.imposed.push_back({n, DX, 0.0}), plate.imposed.push_back({n, DY, 0.0});
  MechanicalLoads loads;
  loads.multipliers.push_back([](double t) { return t; });
  auto hook = make_relations_hook(plate.relations, loads.multipliers, nullptr);
  EXPECT_FALSE(hook->has_contact());
  std::ostringstream out;
  lunaster::Log log(out, 1);
  SolveResult r;
  ASSERT_NO_THROW(r = solve(model, plate.imposed, {}, *hook, log)) << out.str();
  for (int n : tb.cd_nodes) EXPECT_NEAR(r.u[r.dofs.dof(n, DY)], -0.1, 1e-13);
  EXPECT_EQ(r.n_settle, 0);
  EXPECT_EQ(out.str().find("contact"), std::string::npos) << out.str();
}

TEST(RelationsHook, EliminatedChainsAreClosedAndGiveWhatTheMultipliersGive) {
  // The upper block on a fixed base (AB clamped), its top nodes chained: DY(n_i+1) - DY(n_i) = 0,
  // listed from the last node (each relation's pivot is in the expression of the one before, which
  // the elimination then closes), DX(last) - DX(first) = 0.01 t (a right-hand side following the load), and DY of the
  // first top node imposed. Eliminated and dualised, the same state to round-off; a relation that
  // repeats the chain's sum stops the eliminated run, naming it.
  const TwoBlocks tb = make_two_blocks(4, 3, false);
  const FeModel model = make_model(tb.mesh, 2e6, 0.3);
  std::vector<Imposed> imposed;
  for (const int n : tb.mesh.nodes_of_cells(tb.ab)) imposed.push_back({n, DX, 0.0}), imposed.push_back({n, DY, 0.0});
  for (int n : tb.gh_nodes) imposed.push_back({n, DX, 0.0}), imposed.push_back({n, DY, 0.0});  // the other block
  imposed.push_back({tb.cd_nodes[0], DY, -0.1});
  imposed.push_back({tb.cd_nodes[0], DX, 0.0});
  std::vector<LinearRelation> relations;
  for (size_t i = tb.cd_nodes.size() - 1; i > 0; --i) {  // from the end: each pivot is in the expression before
    LinearRelation r;
    r.terms = {{tb.cd_nodes[i], DY, 2.0}, {tb.cd_nodes[i - 1], DY, -2.0}};
    relations.push_back(r);
  }
  LinearRelation shear;
  shear.terms = {{tb.cd_nodes.back(), DX, 1.0}, {tb.cd_nodes[0], DX, -1.0}};
  shear.value = 0.01, shear.load = 0;
  relations.push_back(shear);
  MechanicalLoads loads;
  loads.multipliers.push_back([](double t) { return t; });
  std::ostringstream out;
  lunaster::Log log(out, 1);
  SolveResult with_multipliers, eliminated;
  auto dual = make_relations_hook(relations, loads.multipliers, nullptr, false);
  auto elim = make_relations_hook(relations, loads.multipliers, nullptr, true);
  ASSERT_NO_THROW(with_multipliers = solve(model, imposed, {}, *dual, log)) << out.str();
  ASSERT_NO_THROW(eliminated = solve(model, imposed, {}, *elim, log)) << out.str();
  EXPECT_EQ(elim->matrix_kind(), MatrixKind::SymmetricPositiveDefinite);
  EXPECT_EQ(dual->matrix_kind(), MatrixKind::SymmetricIndefinite);
  ASSERT_EQ(with_multipliers.dofs.n_dofs(), eliminated.dofs.n_dofs() + static_cast<int>(relations.size()));
  for (int eq = 0; eq < eliminated.dofs.n_dofs(); ++eq)
    EXPECT_NEAR(eliminated.u[eq], with_multipliers.u[eq], 1e-13) << "equation " << eq;
  for (int n : tb.cd_nodes) EXPECT_NEAR(eliminated.u[eliminated.dofs.dof(n, DY)], -0.1, 1e-14);
  EXPECT_NEAR(eliminated.u[eliminated.dofs.dof(tb.cd_nodes.back(), DX)], 0.01, 1e-14);
  EXPECT_GT(std::abs(eliminated.u[eliminated.dofs.dof(tb.cd_nodes[2], DX)]), 1e-4);  // the top is sheared
  // DY(last) - DY(first) = 0 is the chain's sum: no unknown is left to solve it for.
  LinearRelation sum;
  sum.terms = {{tb.cd_nodes.back(), DY, 1.0}, {tb.cd_nodes[1], DY, -1.0}};
  relations.push_back(sum);
  auto redundant = make_relations_hook(relations, loads.multipliers, nullptr, true);
  try {
    solve(model, imposed, {}, *redundant, log);
    FAIL() << "no error";
  } catch (const lunaster::DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("linear relation " + std::to_string(relations.size()) +
                                         " is a combination of the relations before it"),
              std::string::npos)
        << e.what();
  }
}

TEST(LinearRelations, OneTermRelationsBecomeDirichletValuesAndRepeatedTermsAddUp) {
  std::vector<DirichletValue> dirichlet;
  LinearRelation one;  // 2 DX(5) = 0.2, with a second term on DX(5) that adds to it: 4 DX(5) = 0.2
  one.terms = {{5, DX, 2.0}, {5, DX, 2.0}};
  one.value = 0.2, one.load = 3;
  LinearRelation cancels;  // DY(1) - DY(1) + DX(2) = 0: DX(2) = 0
  cancels.terms = {{1, DY, 1.0}, {1, DY, -1.0}, {2, DX, 1.0}};
  LinearRelation two;
  two.terms = {{7, DY, 1.0}, {8, DY, -1.0}};
  const auto left = split_dirichlet({one, cancels, two}, dirichlet);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].terms.size(), 2u);
  ASSERT_EQ(dirichlet.size(), 2u);
  EXPECT_EQ(dirichlet[0].node, 5);
  EXPECT_DOUBLE_EQ(dirichlet[0].value, 0.05);
  EXPECT_EQ(dirichlet[0].load, 3);
  EXPECT_EQ(dirichlet[1].node, 2);
  EXPECT_EQ(dirichlet[1].component, DX);
  EXPECT_EQ(dirichlet[1].value, 0.0);
}

TEST(LinearRelations, CarriersAreFreeSlotsOfTheTermsNodesAndTheRightHandSideFollowsItsLoad) {
  Mesh mesh;
  mesh.dim = 2;
  for (int i = 0; i < 4; ++i) mesh.add_node(i, 0.0, 0.0);
  mesh.add_cell(CellType::Quad4, {0, 1, 2, 3});
  DofMap dofs(mesh, {0}, 2);
  LinearRelations relations;
  for (int k = 0; k < 4; ++k) {  // four relations on nodes 0 and 1: 0 gets three, 1 the fourth
    LinearRelation r;
    r.terms = {{0, DX, 1.0}, {1, DX, -1.0}};
    r.value = 1.0 + k, r.load = 0;
    relations.add(r);
  }
  relations.add_dofs(dofs, {});
  const auto& rs = relations.relations();
  EXPECT_EQ(rs[0].carrier_node, 0);
  EXPECT_EQ(rs[2].carrier_component, LAGR_DZ);
  EXPECT_EQ(rs[3].carrier_node, 1);
  EXPECT_EQ(rs[3].carrier_component, LAGR_DX);
  EXPECT_EQ(dofs.n_dofs(), 8 + 4);
  Vector u = Vector::Zero(dofs.n_dofs()), residual = Vector::Zero(dofs.n_dofs());
  u[dofs.dof(0, DX)] = 0.5;
  relations.add_residual(dofs, u, residual, [](int load) { return load == 0 ? 0.25 : 1.0; });
  EXPECT_DOUBLE_EQ(residual[rs[3].multiplier], 0.5 - 4.0 * 0.25);
  // A fifth relation on the same two nodes has no slot left: the error says what to do.
  LinearRelations more = relations;
  LinearRelation r;
  r.terms = {{0, DY, 1.0}, {1, DY, -1.0}};
  more.add(r);
  DofMap fresh(mesh, {0}, 2);
  for (int k = 0; k < 3; ++k) fresh.add(1, LAGR_DX + k);  // node 1's slots taken first (as contact ties take theirs)
  try {
    more.add_dofs(fresh, {});
    FAIL() << "no error";
  } catch (const lunaster::DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("linear relation 5"), std::string::npos) << e.what();
  }
  // A relation that says where it comes from is named so (AFFE_CHAR_MECA and STAT_NON_LINE label the deck's).
  r.label = "LIAISON_DDL[2] of CHARGE 'CH'";
  LinearRelations labelled = relations;
  labelled.add(r);
  DofMap again(mesh, {0}, 2);
  for (int k = 0; k < 3; ++k) again.add(1, LAGR_DX + k);
  try {
    labelled.add_dofs(again, {});
    FAIL() << "no error";
  } catch (const lunaster::DeckError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("LIAISON_DDL[2] of CHARGE 'CH': every node of it", 0), 0u) << e.what();
  }
}

}  // namespace
