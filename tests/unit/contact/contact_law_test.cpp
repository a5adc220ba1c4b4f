// The laws on their own (contact_law.hpp): statuses and coefficients as the shared parts read them.
#include <gtest/gtest.h>

#include <vector>

#include "engine/contact/contact_law.hpp"

namespace {

using namespace lunaster::engine;
using namespace lunaster::engine::contact;

ContactPoint paired_point(bool active) {
  ContactPoint p;
  p.paired = true;
  p.active = active;
  p.wjac = 0.5;
  return p;
}

// Mortar's primal-dual active set: C = p - max(0, p - c g) with p = -lambda the pressure in
// compression; a status changes only beyond round-off (1e-9 of the largest active pressure and
// of c h), so that a converged iterate does not flip back and forth.
TEST(ComplementarityLaw, StatusesChangeOnlyBeyondRoundOff) {
  const auto law = make_complementarity_law();
  EXPECT_TRUE(law->exact_by_elimination());
  EXPECT_FALSE(law->has_multipliers());
  EXPECT_TRUE(law->relative_coefficient());
  const double c = 1e7, h = 0.1;  // c h = 1e6 Pa: the gap tolerance is 1e-9 h
  const std::vector<double> rho = {c}, min_edge = {h};
  // 0: active, compressed; 1: active, tension within round-off; 2: active, tension beyond it;
  // 3: inactive, penetration within round-off; 4: inactive, penetration beyond it; 5: inactive,
  // open; 6: unpaired but active.
  std::vector<ContactPoint> points = {paired_point(true),  paired_point(true),  paired_point(true),
                                      paired_point(false), paired_point(false), paired_point(false),
                                      paired_point(true)};
  points[6].paired = false;
  const double lambda_max = 1e5;
  const std::vector<double> lambda = {-lambda_max, 0.5e-9 * lambda_max, 1e-3 * lambda_max, 0.0, 0.0, 0.0, 0.0};
  const std::vector<double> gap = {0.0, 0.0, 0.0, -0.5e-9 * h, -1e-6 * h, 1e-3 * h, 0.0};
  const int changed = law->update_statuses(points, StatusInputs{lambda, gap, min_edge}, rho);
  const std::vector<bool> expected = {true, true, false, false, true, false, false};
  for (size_t i = 0; i < points.size(); ++i) EXPECT_EQ(points[i].active, expected[i]) << "point " << i;
  EXPECT_EQ(changed, 3);
  // An active point holds g = 0 exactly (alpha = sigma = w, no penalty, no regularisation);
  // an inactive one adds nothing.
  const PointCoefficients on = law->coefficients(paired_point(true), c);
  EXPECT_EQ(on.alpha, 0.5);
  EXPECT_EQ(on.sigma, 0.5);
  EXPECT_EQ(on.beta, 0.0);
  EXPECT_EQ(on.kappa, 0.0);
  const PointCoefficients off = law->coefficients(paired_point(false), c);
  EXPECT_EQ(off.alpha + off.beta + off.sigma + off.kappa, 0.0);
}

// The other laws keep their multipliers or act through the gap; none eliminates.
TEST(ContactLaws, OnlyTheComplementarityLawEliminates) {
  EXPECT_FALSE(make_augmented_lagrangian_law()->exact_by_elimination());
  EXPECT_FALSE(make_active_set_law()->exact_by_elimination());
  EXPECT_FALSE(make_penalty_law()->exact_by_elimination());
  EXPECT_FALSE(make_spring_law()->exact_by_elimination());
  EXPECT_FALSE(make_penalty_law()->relative_coefficient());
}

}  // namespace
