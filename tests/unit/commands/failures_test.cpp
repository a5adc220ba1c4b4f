// commands/failures.cpp: engine failures said again in the deck's keywords. The engine's
// own phrasing (tests/unit/nonlinear) names no keyword; these tests pin the translation.
#include <gtest/gtest.h>

#include "commands/failures.hpp"
#include "engine/assembly/assembly.hpp"
#include "engine/core/error.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/mesh/mesh.hpp"
#include "engine/nonlinear/tangent_source.hpp"
#include "tests/unit/fe/axis_past_the_axis.hpp"
#include "tests/unit/fe/hardening_bar.hpp"

namespace {

using lunaster::Failure;
using lunaster::SolveError;

std::string text(const lunaster::Error& e) {
  std::string t = e.message();
  for (const auto& h : e.hints()) t += "\n" + h;
  return t;
}

TEST(FailureKeywords, NewtonNamesIterGlobMaxiAndTheResiduals) {
  SolveError e("Newton did not converge at instant 1.000000e+00 within 6 iterations",
               {"last residuals: relative 1.2e-03, absolute 4.5e+01 N", "loop: Newton (contact/geometry fixed-point pass 0)",
                "step [0, 1] still failed after 2 subdivision level(s)",
                "failed in step 2 of 2 [2.5e-01, 1]; 1 step(s) converged before, the last at instant 2.5e-01 "
                "(stored step 1)"});
  e.failure().what = Failure::What::NewtonIterations;
  e.failure().limit = 6;
  e.failure().residuals_known = true;
  e.failure().subdivision_levels = 2;
  lunaster::cmd::say_in_keywords(e);
  EXPECT_EQ(e.message(), "Newton did not converge at instant 1.000000e+00 within ITER_GLOB_MAXI = 6 iterations");
  EXPECT_EQ(e.hints()[0], "last residuals: RESI_GLOB_RELA = 1.2e-03, RESI_GLOB_MAXI = 4.5e+01");
  EXPECT_EQ(e.hints()[2], "step [0, 1] still failed after 2 subdivision level(s) (SUBD_NIVEAU)");
  EXPECT_EQ(e.hints()[3],
            "failed in step 2 of 2 [2.5e-01, 1]; 1 step(s) converged before, the last at instant 2.5e-01 "
            "(NUME_ORDRE 1)");
}

TEST(FailureKeywords, ContactLoopsNameTheirLimits) {
  SolveError status("contact status loop did not settle after 30 iterations: 4 contact point(s) still change status",
                    {"points cycling between contact and no contact: statuses updated inside Newton, another "
                     "coefficient, or a finer/compatible mesh may settle them"});
  status.failure().what = Failure::What::StatusLoop;
  status.failure().limit = 30;
  lunaster::cmd::say_in_keywords(status);
  EXPECT_NE(text(status).find("after 30 iterations (ITER_CONT_MAXI): 4 contact point(s)"), std::string::npos) << text(status);
  EXPECT_NE(text(status).find("ALGO_RESO_CONT='NEWTON'"), std::string::npos) << text(status);

  // The discrete formulation's loop, bounded per contact point (ITER_CONT_MULT).
  SolveError discrete("contact status loop did not settle after 160 iterations: 1 contact point(s) still change status",
                      {"the active set changes one contact point per iteration: more iterations per point, or fewer "
                       "points active at the start, may settle it"});
  discrete.failure().what = Failure::What::StatusLoop;
  discrete.failure().limit = 160;
  discrete.failure().per_point = 4;
  lunaster::cmd::say_in_keywords(discrete);
  EXPECT_EQ(discrete.message(), "contact status loop did not settle after 160 iterations (ITER_CONT_MULT = 4 per "
                                "contact point, 40 points): 1 contact point(s) still change status");
  EXPECT_NE(text(discrete).find("raise ITER_CONT_MULT or ITER_CONT_MAXI"), std::string::npos) << text(discrete);
  EXPECT_EQ(text(discrete).find("ALGO_RESO_CONT='NEWTON'"), std::string::npos) << text(discrete);

  SolveError geom("contact geometry loop did not converge after 10 re-pairings: geometric residual 0.5 > tolerance 0.01",
                  {"more re-pairings, smaller load increments or pairing inside Newton may help"});
  geom.failure().what = Failure::What::GeometryLoop;
  geom.failure().limit = 10;
  lunaster::cmd::say_in_keywords(geom);
  EXPECT_EQ(geom.message(),
            "contact geometry loop did not converge after 10 iterations (ITER_GEOM_MAXI): geometric residual 0.5 > "
            "RESI_GEOM 0.01");
  EXPECT_NE(text(geom).find("ALGO_RESO_GEOM='NEWTON'"), std::string::npos);
}

TEST(FailureKeywords, AnAxisymmetricCellIsAnAxisOne) {
  // The engine's own refusal (a TRIA6 curved past the axis puts an integration point at r <= 0, as in
  // tests/unit/fe/axis_test.cpp) names the cell's modelling in engine words; the deck's is 'AXIS'.
  using namespace lunaster::engine;
  const Mesh mesh = test::tria6_past_the_axis();
  FeModel model;
  model.mesh = &mesh;
  model.dim = 2;
  model.materials = {ElasticMaterial{2.0e6, 0.3, 0.0}};
  model.modelisation = {Modelisation::Axisymmetric};
  model.material = {0};
  const DofMap dofs(mesh, {0}, 2);
  std::vector<Triplet> triplets;
  try {
    assemble_stiffness(model, dofs, triplets);
    FAIL() << "expected a DeckError";
  } catch (lunaster::DeckError& e) {
    EXPECT_NE(e.message().find("cell M1 (axisymmetric): integration point at radius"), std::string::npos) << e.message();
    lunaster::cmd::say_in_keywords(e);
    EXPECT_NE(e.message().find("cell M1 (AXIS): integration point at radius"), std::string::npos) << e.message();
  }
}

TEST(FailureKeywords, BehaviourFailuresNameTheStepSplitAndTheLayouts) {
  // The driver's own errors (tangent_source.hpp): a failed integration points to the step's
  // subdivision; a nonlinear behaviour on a shared model or a mesh in parts to the settings that
  // keep the model whole.
  using namespace lunaster::engine;
  ConvergenceError failed = integration_failure(2.0);
  EXPECT_EQ(text(failed).find("SUBD"), std::string::npos) << text(failed);
  lunaster::cmd::say_in_keywords(failed);
  EXPECT_NE(text(failed).find("(DEFI_LIST_INST), or let the step be subdivided (ECHEC SUBD_NIVEAU, SUBD_PAS)"),
            std::string::npos)
      << text(failed);

  Mesh mesh;
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) mesh.add_node(x, y, 0.0);
  mesh.add_cell(CellType::Quad4, {0, 1, 2, 3});
  mesh.detect_dimension();
  FeModel model;
  model.mesh = &mesh;
  model.dim = 2;
  model.materials = {ElasticMaterial{hardening_bar::kE, 0.0, 0.0}};
  model.modelisation = {Modelisation::PlaneStrain};
  model.material = {0};
  const DofMap dofs(mesh, {0}, 2);
  CellBehaviours behaviours(model);
  EXPECT_EQ(make_behaviour_tangent(behaviours, dofs, RankLayout::Kind::Shared), nullptr) << "linear: the elastic path";
  behaviours.assign({0}, std::make_shared<hardening_bar::HardeningBar>());
  EXPECT_NE(make_behaviour_tangent(behaviours, dofs, RankLayout::Kind::Whole), nullptr);
  for (const auto kind : {RankLayout::Kind::Shared, RankLayout::Kind::InParts}) {
    try {
      make_behaviour_tangent(behaviours, dofs, kind);
      FAIL() << "expected a DeckError";
    } catch (lunaster::DeckError& e) {
      EXPECT_EQ(text(e).find("COMPORTEMENT"), std::string::npos) << text(e);
      lunaster::cmd::say_in_keywords(e);
      EXPECT_NE(text(e).find(kind == RankLayout::Kind::Shared ? "MATR_DISTRIBUEE='OUI'" : "PARTITIONNEUR"),
                std::string::npos)
          << text(e);
    }
  }
}

TEST(FailureKeywords, AnUntypedErrorIsLeftAlone) {
  SolveError e("MUMPS: error during factorisation: INFOG(1) = -5", {"a hint"});
  lunaster::cmd::say_in_keywords(e);
  EXPECT_EQ(text(e), "MUMPS: error during factorisation: INFOG(1) = -5\na hint");
}

}  // namespace
